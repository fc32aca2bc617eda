#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "cosmems/analysis/buckling_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// The first buckling mode of a frame under a load pattern.
struct FrameBucklingResult {
  Status status = Status::kOk;
  /// lambda: the loads times lambda buckle the frame (linear buckling about the unloaded shape).
  double load_factor = 0.0;
  /// N: lambda times the largest compressive member force under the loads as given.
  double critical_load_n = 0.0;
  Eigen::VectorXd shape;          ///< reduced, internal units, largest entry +1
  Eigen::VectorXd axial_force_n;  ///< each element's axial force under the loads as given
  bool compressed = false;        ///< whether the loads compress any member beyond round-off
};

namespace internal {

// The lowest positive lambda of (k + lambda K_G) x = 0, K_G = sum_e N_e G_e for the elements'
// axial forces `axial` (internal units), into out (load_factor, critical_load_n: lambda times
// the largest compression, shape).
inline void SolveBucklingOfAxialForces(const FrameModel& model, const SymmetricBandMatrix& k,
                                       const Eigen::VectorXd& axial, const BucklingOptions& options,
                                       FrameBucklingResult& out) {
  SymmetricBandMatrix compression(k.size(), k.bandwidth());  // -K_G
  double largest = 0.0;
  for (int e = 0; e < model.ElementCount(); ++e) {
    largest = std::max(largest, -axial[e] * model.units().force);
    model.AddElementMatrix(e, -axial[e] * model.elements()[e].Geometric(model.bases(), 0),
                           compression);
  }
  const BucklingResult buckling = SolveBucklingPencil(k, compression, 1.0, options);
  out.status = buckling.status;
  if (buckling.status != Status::kOk) return;
  out.load_factor = buckling.modes.at(0).critical_load_n;
  out.critical_load_n = out.load_factor * largest;
  out.shape = buckling.modes[0].shape;
}

}  // namespace internal

/// Linear buckling of a frame: the members' axial forces N_e under `loads` (linear statics)
/// give the geometric stiffness K_G = sum_e N_e G_e (each element's G_0, rotated like its K), and
/// (K + lambda K_G) x = 0 the lowest positive load factor lambda. A frame none of whose members
/// the loads compress has none (Status::kNotConverged, `compressed` false): a compression below
/// 1e-9 of the loads' forces (and of the largest member force) is round-off, such as that of a
/// folded flexure pulled along its compliant direction.
inline FrameBucklingResult SolveFrameBuckling(const FrameModel& model, const FrameLoadCase& loads,
                                              const BucklingOptions& options = {}) {
  FrameBucklingResult out;
  Eigen::VectorXd d;
  out.status = SolveFrameDisplacement(model, AssembleFrameLoads(model, loads), d);
  if (out.status != Status::kOk) return out;
  Eigen::VectorXd axial(model.ElementCount());
  out.axial_force_n.resize(model.ElementCount());
  double largest = 0.0;
  double magnitude = 0.0;  // the loads' forces: |F| of each point load, |q| over every member
  for (const FramePointLoad& load : loads.points) magnitude += load.force.norm();
  for (const FrameMesh::Element& element : model.mesh().elements) {
    magnitude += loads.distributed.norm() * element.length;
  }
  for (int e = 0; e < model.ElementCount(); ++e) {
    const FrameModel::ElementVector end = internal::ElementEndForces(model, d, e, loads);
    // The mean of the two ends' tension: exact for point loads, the element's average under a
    // distributed axial load. A member's residual force is not the loads' and is not scaled
    // with them: it stays in K as its N G_0.
    axial[e] = 0.5 * (end[6] - end[0]) - model.ElementAxialLoad(e);
    out.axial_force_n[e] = axial[e] * model.units().force;
    largest = std::max(largest, -out.axial_force_n[e]);
    magnitude = std::max(magnitude, std::abs(out.axial_force_n[e]));
  }
  out.compressed = largest > 1e-9 * magnitude;
  if (!out.compressed) {
    out.status = Status::kNotConverged;
    return out;
  }
  internal::SolveBucklingOfAxialForces(model, model.Stiffness(), axial, options, out);
  return out;
}

/// Euler buckling of a straight member (a cantilever's or a bridge's): every element of `member`
/// under the same axial compression, (K_e - lambda G) x = 0, where K_e leaves out the members'
/// residual axial loads. lambda, `critical_load_n`, is the total compressive force the member
/// carries when it buckles, whatever residual force it already holds.
inline FrameBucklingResult SolveMemberBuckling(const FrameModel& model, int member,
                                               const BucklingOptions& options = {}) {
  FrameBucklingResult out;
  SymmetricBandMatrix elastic = model.Stiffness();
  Eigen::VectorXd axial = Eigen::VectorXd::Zero(model.ElementCount());
  for (int e = 0; e < model.ElementCount(); ++e) {
    const double residual = model.ElementAxialLoad(e);
    if (residual != 0.0) {
      model.AddElementMatrix(e, -residual * model.elements()[e].Geometric(model.bases(), 0),
                             elastic);
    }
    if (model.mesh().elements[e].member == member) axial[e] = -1.0 / model.units().force;
  }
  out.axial_force_n = axial * model.units().force;
  out.compressed = true;
  internal::SolveBucklingOfAxialForces(model, elastic, axial, options, out);
  return out;
}

}  // namespace cosmems
