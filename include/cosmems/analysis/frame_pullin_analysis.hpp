#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"

namespace cosmems {

/// A device over parallel-plate electrodes: where they lie, and how the fold is traced.
struct FramePullInOptions {
  FrameGapOptions electrodes;
  bool fringing = false;
  FoldOptions fold;
  NewtonOptions newton;
};

/// The electrostatic pressure on a frame's faces over its electrodes, at `voltage`.
inline FrameGapForce<ElectrostaticPressure> MakeFrameElectrostaticForce(
    const FrameModel& model, const FramePullInOptions& options, double voltage) {
  return FrameGapForce<ElectrostaticPressure>(
      model, ElectrostaticPressure{voltage, 0.0, options.fringing}, options.electrodes);
}

/// A device's pull-in: the fold, the carrier whose travel was held, and the shape of the last
/// stable state with everything SolveFrameStatic recovers (reactions and stresses under the
/// voltage that holds it, a hair below the pull-in voltage).
struct FramePullInResult {
  PullInResult fold;
  int control_carrier = -1;  ///< the FrameMesh carrier (a node or a body)
  FrameStaticSolution shape;
  double capacitance_f = 0.0;  ///< of the faces over the electrodes, at rest
};

/// The carrier that moves most toward the substrate under the electrostatic pressure at rest
/// (the linear response to the pressure at 1 V): where the travel is best held, since it moves
/// monotonically up to the fold. -1 when K is singular (a mechanism) or nothing is pulled.
inline int PullInControlCarrier(const FrameModel& model,
                                FrameGapForce<ElectrostaticPressure>& unit) {
  const int n = model.FreeDofCount();
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n), d;
  ForceTangent tangent(n, model.Stiffness().bandwidth());
  if (!unit.Evaluate(Eigen::VectorXd::Zero(n), r, tangent)) return -1;
  if (SolveFrameDisplacement(model, r, d) != Status::kOk) return -1;
  int best = -1;
  double largest = 0.0;
  for (int c = 0; c < static_cast<int>(model.mesh().carriers.size()); ++c) {
    const int dof = model.CarrierDof(c, 1);
    if (dof >= 0 && std::abs(d[dof]) > largest) {
      largest = std::abs(d[dof]);
      best = c;
    }
  }
  return best;
}

/// The pull-in voltage of a device over electrodes, by displacement control (FoldPath) of the
/// carrier that moves most (PullInControlCarrier): the voltage at the fold, the deflection there,
/// and the shape of the last stable state. `others` add their forces (the members' stretching).
/// A mechanism is Status::kNotPositiveDefinite; no fold before 99 % of the gap, or none below
/// options.fold.max_load, Status::kNotConverged.
inline FramePullInResult SolveFramePullIn(const FrameModel& model,
                                          const FramePullInOptions& options,
                                          const std::vector<FrameElementForce*>& others = {}) {
  FramePullInResult out;
  FrameGapForce<ElectrostaticPressure> unit = MakeFrameElectrostaticForce(model, options, 1.0);
  out.capacitance_f = unit.Capacitance(Eigen::VectorXd::Zero(model.FreeDofCount()));
  out.control_carrier = PullInControlCarrier(model, unit);
  if (out.control_carrier < 0) {
    out.fold.status = Status::kNotPositiveDefinite;
    return out;
  }
  OutputPoint control;
  control.weights = {{model.CarrierDof(out.control_carrier, 1), 1.0}};
  control.length_unit = model.units().length;
  ForceSum sum;
  for (FrameElementForce* force : others) sum.Add(*force);
  const double gap = options.electrodes.gap;
  FoldPath<FrameModel, FrameGapForce<ElectrostaticPressure>> path(
      model, unit, control, gap, options.newton, others.empty() ? nullptr : &sum);
  out.fold = TraceFold(path, options.fold, gap);
  if (out.fold.status != Status::kOk) return out;
  out.shape.displacement = out.fold.displacement;
  unit.SetScale(path.accepted_load());  // V^2: the pressure that holds the last stable state
  std::vector<FrameElementForce*> forces = others;
  forces.push_back(&unit);
  internal::RecoverFrameStatic(model, FrameLoadCase{}, forces, out.shape);
  out.fold.displacement_m = out.shape.max_deflection;
  return out;
}

}  // namespace cosmems
