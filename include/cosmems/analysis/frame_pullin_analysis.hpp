#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "cosmems/analysis/frame_pullin_options.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"

namespace cosmems {

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
int PullInControlCarrier(const FrameModel& model, FrameGapForce<ElectrostaticPressure>& unit);

/// The pull-in voltage of a device over electrodes, by displacement control (FoldPath) of the
/// carrier that moves most (PullInControlCarrier): the voltage at the fold, the deflection there,
/// and the shape of the last stable state. `others` add their forces (the members' stretching).
/// A mechanism is Status::kNotPositiveDefinite; no fold before 99 % of the gap, or none below
/// options.fold.max_load, Status::kNotConverged.
FramePullInResult SolveFramePullIn(const FrameModel& model, const FramePullInOptions& options,
                                   const std::vector<FrameElementForce*>& others = {});

}  // namespace cosmems
