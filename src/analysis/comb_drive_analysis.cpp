#include "cosmems/analysis/comb_drive_analysis.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cosmems/analysis/comb_drive_force.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/linalg/spd_solver.hpp"

namespace cosmems {

namespace internal {

// The displacement [m] of body `at` along `along` under a 1 N force along `pushed` at body
// `load` (K^-1 by the factor `solver`).
double BodyCompliance(const FrameModel& model, const SpdSolver& solver, int load,
                      const Eigen::Vector3d& pushed, int at, const Eigen::Vector3d& along) {
  FrameLoadCase unit;
  unit.points.push_back({-1, load, pushed, Eigen::Vector3d::Zero()});
  Eigen::VectorXd u = AssembleFrameLoads(model, unit);
  solver.SolveInPlace(u);
  const int carrier = model.mesh().body_carrier[at];
  return model.CarrierMotion(u, carrier).head<3>().dot(along) * model.units().length;
}

bool AnyCombVoltage(const std::vector<CombDrive>& combs) {
  for (const CombDrive& comb : combs) {
    if (comb.voltage != 0.0) return true;
  }
  return false;
}

// The combs, each at the voltage its factor scales: its own, or 1 V each when all are at 0 V.
std::vector<CombDrive> ScaledCombs(std::vector<CombDrive> combs) {
  if (!AnyCombVoltage(combs)) {
    for (CombDrive& comb : combs) comb.voltage = 1.0;
  }
  return combs;
}

// The loads with each comb's engagement force at `factor` times its voltage at its body.
FrameLoadCase WithCombForces(FrameLoadCase loads, const std::vector<CombDrive>& combs,
                             double factor) {
  for (const CombDrive& comb : combs) {
    loads.points.push_back(
        {-1, comb.body, comb.Force(factor * comb.voltage) * comb.Axis(), Eigen::Vector3d::Zero()});
  }
  return loads;
}

// The lowest factor in (lo, 1e6] at which `stable` turns false, bracketed by doubling from 1 and
// bisected to `tolerance` of itself; `lo` ends at the last stable factor tried (infinity and lo
// unchanged when every factor up to 1e6 is stable).
template <class Stable>
double FirstUnstableFactor(Stable&& stable, double tolerance, double& lo) {
  double hi = 1.0;
  while (stable(hi)) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return std::numeric_limits<double>::infinity();
  }
  while (hi - lo > tolerance * hi) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (stable(mid) ? lo : hi) = mid;
  }
  return hi;
}

// Linear statics with the combs' forces as loads, and the side instability in closed form: with
// every comb's voltage scaled by s, each comb's engagement x_c(s) (the loads held, the combs'
// forces growing as s^2) and its negative stiffness k_c(s) across its fingers, the suspension
// gives way sideways at the lowest s where K - sum_c k_c l_c l_c^T turns singular: where the
// largest eigenvalue of D C D, C the bodies' compliance across the combs (C_ij: body i's motion
// along l_i under 1 N along l_j at body j) and D = diag(sqrt(k_c)), reaches 1. For one comb
// this is k_c(s) = 1 / C, the suspension's stiffness across the fingers (Legtenberg et al.
// 1996).
CombDriveSolution SolveLinearCombDrives(const FrameModel& model, const FrameLoadCase& loads,
                                        const std::vector<CombDrive>& declared) {
  CombDriveSolution out;
  out.statics = SolveFrameStatic(model, WithCombForces(loads, declared, 1.0));
  if (out.statics.status != Status::kOk || declared.empty()) return out;
  const std::vector<CombDrive> combs = ScaledCombs(declared);
  const int m = static_cast<int>(combs.size());
  SpdSolver solver;
  if (solver.Compute(model.Stiffness(), SpdSolverKind::kAuto) != Status::kOk) return out;
  Eigen::MatrixXd lateral(m, m), engagement(m, m);
  Eigen::VectorXd held(m);  // the engagement of the scene's loads alone
  for (int i = 0; i < m; ++i) {
    const CombDrive& c = declared[i];
    CombDriveState& state = out.combs.emplace_back();
    state.force_n = c.Force(c.voltage);
    state.engagement_m = out.statics.bodies[c.body].head<3>().dot(c.Axis());
    state.offset_m = out.statics.bodies[c.body].head<3>().dot(c.Lateral());
    state.capacitance_f = c.Capacitance(state.engagement_m);
    held[i] = state.engagement_m;
    for (int j = 0; j < m; ++j) {
      const CombDrive& d = combs[j];
      lateral(i, j) = BodyCompliance(model, solver, d.body, d.Lateral(), c.body, c.Lateral());
      engagement(i, j) = BodyCompliance(model, solver, d.body, d.Axis(), c.body, c.Axis());
      held[i] -= engagement(i, j) * declared[j].Force(declared[j].voltage);
    }
  }
  // Whether the largest eigenvalue of D C D at the factor s stays below one.
  const auto stable = [&](double s) {
    ++out.solves;
    Eigen::VectorXd root(m);
    for (int i = 0; i < m; ++i) {
      double x = held[i];
      for (int j = 0; j < m; ++j) x += engagement(i, j) * combs[j].Force(s * combs[j].voltage);
      root[i] = std::sqrt(combs[i].SideStiffness(s * combs[i].voltage, x));
    }
    const Eigen::MatrixXd scaled = root.asDiagonal() * lateral * root.asDiagonal();
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled, Eigen::EigenvaluesOnly)
               .eigenvalues()
               .maxCoeff() < 1.0;
  };
  double lo = 0.0;
  out.side_instability_factor = FirstUnstableFactor(stable, 1e-15, lo);
  if (!std::isfinite(out.side_instability_factor)) return out;
  out.last_stable_factor = lo;
  out.last_stable = SolveFrameStatic(model, WithCombForces(loads, combs, lo));
  return out;
}

// The combs' pull as a force Newton's statics ramp with the loads and the pressures across the
// gap: all grow with V^2 from nothing. Held whole from the first iterate, a comb's force leaves
// Newton far from the equilibrium of a structure its other forces stiffen or soften, and a failed
// solve would read as an instability. It acts on the bodies alone: no element carries a share.
class RampedCombs final : public FrameElementForce {
 public:
  explicit RampedCombs(CombDriveForce& combs) : combs_(combs) {}

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    return combs_.Evaluate(d, force, tangent);
  }
  FrameModel::ElementVector LocalForce(const Eigen::VectorXd&, int) const override {
    return FrameModel::ElementVector::Zero();
  }

 private:
  CombDriveForce& combs_;
};

// The same under nonlinear forces (CombDriveForce beside `forces`, ramped with the loads and the
// `ramped` pressures): Newton's statics, and the side instability as the lowest factor whose
// equilibrium is lost or whose tangent K + dr/dd is not positive definite, bisected to 1e-10 of
// itself.
CombDriveSolution SolveNonlinearCombDrives(const FrameModel& model, const FrameLoadCase& loads,
                                           const std::vector<CombDrive>& declared,
                                           const std::vector<FrameElementForce*>& forces,
                                           const std::vector<FrameElementForce*>& pressures) {
  CombDriveSolution out;
  CombDriveForce pull(model, ScaledCombs(declared));
  RampedCombs combs(pull);
  std::vector<FrameElementForce*> ramped = pressures;
  ramped.push_back(&combs);
  std::vector<FrameElementForce*> all = forces;
  all.insert(all.end(), ramped.begin(), ramped.end());
  // Each factor's Newton starts from the last stable state found (from rest at first): near
  // it, one load step instead of a ramp.
  NonlinearStaticOptions options;
  const auto solve = [&](double factor) {
    pull.SetVoltageFactor(factor);
    return SolveFrameNonlinearStatic(model, forces, loads, ramped, options);
  };
  out.statics = solve(AnyCombVoltage(declared) ? 1.0 : 0.0);
  if (out.statics.status != Status::kOk || declared.empty()) return out;
  for (int c = 0; c < static_cast<int>(declared.size()); ++c) {
    const CombDrive& comb = declared[c];
    const Eigen::Vector2d xy = pull.Motion(out.statics.displacement, c);
    CombDriveState& state = out.combs.emplace_back();
    state.force_n = comb.Force(comb.voltage, xy[1]);
    state.engagement_m = xy[0];
    state.offset_m = xy[1];
    state.capacitance_f = comb.Capacitance(xy[0], xy[1]);
  }
  const int n = model.FreeDofCount();
  ForceTangent tangent(n, model.Stiffness().bandwidth());
  Eigen::VectorXd r(n);
  SymmetricBandMatrix jacobian(n, model.Stiffness().bandwidth());
  BandRankOneCholesky factor;
  FrameStaticSolution candidate;
  const auto stable = [&](double s) {
    ++out.solves;
    candidate = solve(s);
    if (candidate.status != Status::kOk) return false;
    r.setZero();
    tangent.Clear();
    for (FrameElementForce* force : all) {
      if (!force->Evaluate(candidate.displacement, r, tangent)) return false;
    }
    jacobian.mutable_data() = model.Stiffness().data() + tangent.band().data();
    if (factor.Compute(jacobian, tangent.rank_one_scale(), tangent.rank_one_vector()) !=
        Status::kOk) {
      return false;
    }
    out.last_stable = std::move(candidate);
    out.last_stable_factor = s;
    options.start = out.last_stable.displacement;
    return true;
  };
  double lo = 0.0;
  out.side_instability_factor = FirstUnstableFactor(stable, 1e-10, lo);
  return out;
}

}  // namespace internal

CombDriveSolution SolveCombDrives(const FrameModel& model, const FrameLoadCase& loads,
                                  const std::vector<CombDrive>& combs,
                                  const std::vector<FrameElementForce*>& forces,
                                  const std::vector<FrameElementForce*>& pressures) {
  ValidateCombDrives(combs, static_cast<int>(model.description().bodies.size()));
  CombDriveSolution out =
      forces.empty() && pressures.empty()
          ? internal::SolveLinearCombDrives(model, loads, combs)
          : internal::SolveNonlinearCombDrives(model, loads, combs, forces, pressures);
  const std::vector<CombDrive> scaled = internal::ScaledCombs(combs);
  for (std::size_t c = 0; c < out.combs.size(); ++c) {
    out.combs[c].side_instability_voltage_v =
        out.side_instability_factor * std::abs(scaled[c].voltage);
  }
  return out;
}

FrameDrives CombDriveLoads(const FrameModel& model, const std::vector<CombDrive>& combs) {
  ValidateCombDrives(combs, static_cast<int>(model.description().bodies.size()));
  FrameDrives out;
  out.patterns.resize(model.FreeDofCount(), static_cast<Eigen::Index>(combs.size()));
  for (std::size_t c = 0; c < combs.size(); ++c) {
    FrameLoadCase unit;
    unit.points.push_back(
        {-1, combs[c].body, combs[c].Force(1.0) * combs[c].Axis(), Eigen::Vector3d::Zero()});
    out.patterns.col(static_cast<Eigen::Index>(c)) = AssembleFrameLoads(model, unit);
    out.voltages.push_back(combs[c].Drive());
  }
  return out;
}

}  // namespace cosmems
