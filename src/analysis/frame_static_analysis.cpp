#include "cosmems/analysis/frame_static_analysis.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cosmems {

namespace {

// A point load between a member's nodes: the element holding it and its consistent loads there
// (the element's axes, internal units).
std::pair<int, ElementLoads> MemberPointLoads(const FrameModel& model, const FramePointLoad& load) {
  const UnitSystem& units = model.units();
  const auto [e, xi] = model.Locate(load.member, load.at);
  const Eigen::Matrix3d& axes = model.mesh().elements[e].axes;
  return {e,
          PointElementLoads(model.bases(), model.elements()[e].properties().length, xi,
                            axes * load.force / units.force, axes * load.moment / units.Moment())};
}

bool OnMember(const FrameModel& model, const FramePointLoad& load) {
  return load.node < 0 && load.body < 0 && load.member >= 0 &&
         load.member < static_cast<int>(model.description().members.size());
}

}  // namespace

Eigen::VectorXd AssembleFrameLoads(const FrameModel& model, const FrameLoadCase& loads) {
  const UnitSystem& units = model.units();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.FreeDofCount());
  auto scatter = [&](int e, const ElementLoads& local) {
    const ElementLoads carried = model.ElementTransform(e).transpose() * local;
    for (int a = 0; a < 12; ++a) {
      if (model.ElementDofs(e)[a] >= 0) f[model.ElementDofs(e)[a]] += carried[a];
    }
  };
  for (std::size_t i = 0; i < loads.points.size(); ++i) {
    const FramePointLoad& load = loads.points[i];
    const std::string where = "loads.points[" + std::to_string(i) + "]";
    for (int k = 0; k < 3; ++k) {
      RequireFinite(where + ".force", load.force[k]);
      RequireFinite(where + ".moment", load.moment[k]);
    }
    // A planar structure has no u_z, r_x or r_y: a load along them would be lost.
    if (model.description().planar &&
        (load.force.z() != 0.0 || load.moment.x() != 0.0 || load.moment.y() != 0.0)) {
      throw std::invalid_argument(where +
                                  ": a planar structure moves in the x-y plane alone (no force "
                                  "along z, no moment about x or y)");
    }
    FrameModel::Motion l;
    l << load.force / units.force, load.moment / units.Moment();
    if (load.node >= 0 && load.node < static_cast<int>(model.description().nodes.size())) {
      model.AddNodeLoad(load.node, l, f);
    } else if (load.body >= 0 && load.body < static_cast<int>(model.description().bodies.size())) {
      model.AddCarrierLoad(model.mesh().body_carrier[load.body], l, f);
    } else if (OnMember(model, load)) {
      if (!(load.at >= 0.0 && load.at <= 1.0)) {
        throw std::invalid_argument(where + ".at = " + FormatValue(load.at) +
                                    ": not on the member (0 ... 1)");
      }
      const auto [e, local] = MemberPointLoads(model, load);
      scatter(e, local);
    } else {
      throw std::invalid_argument(where + ": names no node, body or member of the structure");
    }
  }
  for (int k = 0; k < 3; ++k) RequireFinite("loads.distributed", loads.distributed[k]);
  if (model.description().planar && loads.distributed.z() != 0.0) {
    throw std::invalid_argument(
        "loads.distributed: a planar structure moves in the x-y plane alone (no load along z)");
  }
  if (!loads.distributed.isZero(0.0)) {
    for (int e = 0; e < model.ElementCount(); ++e) {
      const FrameMesh::Element& element = model.mesh().elements[e];
      const Eigen::Vector3d q = element.axes * loads.distributed / units.ForcePerLength();
      scatter(e, UniformElementLoads(model.bases(), model.elements()[e].properties().length, q));
    }
  }
  return f;
}

namespace internal {

FrameModel::ElementVector ElementEndForces(const FrameModel& model, const Eigen::VectorXd& d, int e,
                                           const FrameLoadCase& loads,
                                           const std::vector<FrameElementForce*>& forces) {
  const FrameModel::ElementVector u = model.LocalDisplacement(d, e);
  FrameModel::ElementVector s = model.LocalStiffness(e) * u;
  // A residual tension pulls each end toward the other: -N at the first end's u_x, +N at the
  // second's (LocalStiffness already holds its geometric share, N G_0 u).
  s[0] -= model.ElementAxialLoad(e);
  s[6] += model.ElementAxialLoad(e);
  for (const FrameElementForce* force : forces) s += force->LocalForce(d, e);
  if (!loads.distributed.isZero(0.0)) {
    const Eigen::Vector3d q =
        model.mesh().elements[e].axes * loads.distributed / model.units().ForcePerLength();
    s -= UniformElementLoads(model.bases(), model.elements()[e].properties().length, q);
  }
  for (const FramePointLoad& load : loads.points) {
    if (OnMember(model, load) && model.Locate(load.member, load.at).first == e) {
      s -= MemberPointLoads(model, load).second;
    }
  }
  return s;
}

}  // namespace internal

Status SolveFrameDisplacement(const FrameModel& model, const Eigen::VectorXd& f, Eigen::VectorXd& d,
                              SpdSolverKind solver_kind) {
  SpdSolver solver;
  Status status = solver.Compute(model.Stiffness(), solver_kind);
  d = f;
  if (status == Status::kOk) solver.SolveInPlace(d);
  if (status == Status::kOk && !d.allFinite()) status = Status::kNonFinite;
  if (status != Status::kOk) d.setZero();
  return status;
}

namespace internal {

void RecoverFrameMotions(const FrameModel& model, FrameStaticSolution& out) {
  const Eigen::VectorXd& d = out.displacement;
  auto si = [&](FrameModel::Motion m) {
    m.head<3>() *= model.units().length;
    return m;
  };
  for (std::size_t n = 0; n < model.description().nodes.size(); ++n) {
    out.nodes.push_back(si(model.NodeMotion(d, static_cast<int>(n))));
  }
  for (int c : model.mesh().body_carrier) out.bodies.push_back(si(model.CarrierMotion(d, c)));
}

void RecoverFrameStatic(const FrameModel& model, const FrameLoadCase& loads,
                        const std::vector<FrameElementForce*>& forces, FrameStaticSolution& out) {
  const UnitSystem& units = model.units();
  const Eigen::VectorXd& d = out.displacement;
  const StructureDescription& s = model.description();
  RecoverFrameMotions(model, out);

  // Toward the substrate: every mesh node, and every corner of every body.
  for (int n = 0; n < static_cast<int>(model.mesh().nodes.size()); ++n) {
    out.max_deflection = std::max(out.max_deflection, -model.NodeMotion(d, n)[1] * units.length);
  }
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const FrameModel::Motion m = out.bodies[b];
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d r(corner & 1 ? 0.5 : -0.5, corner & 2 ? 0.5 : -0.5,
                              corner & 4 ? 0.5 : -0.5);
      const Eigen::Vector3d u = m.head<3>() + m.tail<3>().cross(r.cwiseProduct(s.bodies[b].size));
      out.max_deflection = std::max(out.max_deflection, -u.y());
    }
  }

  // Element end forces: stresses, axial forces, and what the anchored nodes receive.
  std::vector<FrameModel::Motion> resisted(s.nodes.size(), FrameModel::Motion::Zero());
  for (int e = 0; e < model.ElementCount(); ++e) {
    const FrameModel::ElementVector end = ElementEndForces(model, d, e, loads, forces);
    const ElementProperties& p = model.elements()[e].properties();
    for (int k = 0; k < 2; ++k) {
      const double axial = (k == 0 ? -end[0] : end[6]) * units.force;
      if (std::abs(axial) > std::abs(out.axial_force_n)) out.axial_force_n = axial;
      const double normal = std::abs(end[6 * k]) / p.area +
                            std::abs(end[6 * k + 5]) * p.half_thickness / p.second_moment_z +
                            std::abs(end[6 * k + 4]) * p.half_width / p.second_moment_y;
      // Saint-Venant's largest shear, mid-way along the long side: T c / J with c the short side.
      const double shear = std::abs(end[6 * k + 3]) * 2.0 *
                           std::min(p.half_thickness, p.half_width) / p.torsion_constant;
      const double stress = std::sqrt(normal * normal + 3.0 * shear * shear);
      out.max_stress_pa = std::max(out.max_stress_pa, stress * units.Stress());
    }
    const FrameMesh::Element& element = model.mesh().elements[e];
    const int ends[2] = {element.from, element.to};
    for (int k = 0; k < 2; ++k) {
      if (ends[k] >= static_cast<int>(s.nodes.size())) continue;
      resisted[ends[k]].head<3>() += element.axes.transpose() * end.segment<3>(6 * k);
      resisted[ends[k]].tail<3>() += element.axes.transpose() * end.segment<3>(6 * k + 3);
    }
  }
  for (const FramePointLoad& load : loads.points) {
    if (load.node < 0) continue;
    resisted[load.node].head<3>() -= load.force / units.force;
    resisted[load.node].tail<3>() -= load.moment / units.Moment();
  }
  for (std::size_t n = 0; n < s.nodes.size(); ++n) {
    const AnchorMask& anchor = s.nodes[n].anchor;
    if (std::none_of(anchor.begin(), anchor.end(), [](bool fixed) { return fixed; })) continue;
    FrameReaction reaction{static_cast<int>(n), resisted[n].head<3>() * units.force,
                           resisted[n].tail<3>() * units.Moment()};
    out.reactions.push_back(reaction);
  }
}

}  // namespace internal

FrameStaticSolution SolveFrameStatic(const FrameModel& model, const FrameLoadCase& loads,
                                     SpdSolverKind solver_kind) {
  FrameStaticSolution out;
  out.status = SolveFrameDisplacement(model, AssembleFrameLoads(model, loads), out.displacement,
                                      solver_kind);
  if (out.status == Status::kOk) internal::RecoverFrameStatic(model, loads, {}, out);
  return out;
}

FrameStaticSolution SolveFrameNonlinearStatic(const FrameModel& model,
                                              const std::vector<FrameElementForce*>& forces,
                                              const FrameLoadCase& loads,
                                              const std::vector<FrameElementForce*>& ramped,
                                              const NonlinearStaticOptions& options) {
  FrameStaticSolution out;
  ForceSum held, grown;
  for (FrameElementForce* force : forces) held.Add(*force);
  for (FrameElementForce* force : ramped) grown.Add(*force);
  NonlinearStaticSolve solve(model.Stiffness(), held, options, ramped.empty() ? nullptr : &grown);
  const NonlinearStaticSolution solution = solve.Solve(AssembleFrameLoads(model, loads));
  out.status = solution.status;
  if (out.status != Status::kOk) return out;
  out.displacement = solution.displacement;
  std::vector<FrameElementForce*> all = forces;
  all.insert(all.end(), ramped.begin(), ramped.end());
  internal::RecoverFrameStatic(model, loads, all, out);
  return out;
}

}  // namespace cosmems
