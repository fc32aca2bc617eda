#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/analysis/frame_load_case.hpp"
#include "cosmems/analysis/frame_record_point.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/analysis/transient_result.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/time/voltage_drive.hpp"

namespace cosmems {

/// What voltages drive in a frame's transient, each V(t) of its VoltageDrive: load patterns whose
/// amplitude is their voltage's square (comb drives, whose force does not depend on the motion;
/// each column at 1 V), and a gap force scaled by its voltage's square (the electrodes' pressure
/// at 1 V, which must also be the run's `force` or one of its sum).
struct FrameDrives {
  Eigen::MatrixXd patterns;            ///< n x m, reduced, internal units
  std::vector<VoltageDrive> voltages;  ///< one per column of `patterns`
  FrameGapForce<ElectrostaticPressure>* electrodes = nullptr;
  VoltageDrive electrode_voltage;
};

/// A frame's transient run: its status, steps and timing in `run`, whose output (extremes and
/// divergence check, every step) is the watched component, and the motion of every recorded
/// point at the samples the history keeps.
struct FrameTransientResult {
  TransientResult run;
  /// 0, 1, 2: ux, uy or uz of the first recorded point, the one its static response to the
  /// loads is largest in (uy when the loads do not move it)
  int watched_component = 1;
  /// one row per sample of run.time_s; ux, uy, uz [m] of each recorded point in turn
  Eigen::MatrixXd history;
};

/// The displacement component c (0, 1, 2: global x, y, z) of a recorded point as a linear
/// functional of the reduced displacement: a body's centre reads its own degree of freedom, a
/// node on a body or free reads its carrier's motion through the node's transform, a point
/// along a member its element's interpolation (FrameModel::MemberMotion).
OutputPoint FrameMotionComponent(const FrameModel& model, const FrameRecordPoint& point, int c);

/// A transient run of a frame under `loads` (one spatial pattern times the time function) by
/// the BeamStepper of `options.path` (MakeBeamStepper: the Newmark family on the full band
/// model, or modal propagation with the static correction of the truncated modes), recording
/// the displacement of each point of `record` (at least one). `options.output_x` is not used:
/// the watched output is a component of the first recorded point. A static start deflects the
/// frame under the loads (removed at t = 0); a mechanism is Status::kNotPositiveDefinite. With
/// a nonlinear `force` (the members' stretching; it must outlive the run) the Newmark family
/// takes its Newton path, the modal path holds the force over each step, and a static start
/// solves the nonlinear statics. `drives` add the forces that voltages drive, from t = 0 on
/// whatever the start (at each step their amplitude is V(t)^2 at the step's end); the watched
/// component is then the one the loads and the drives' mean forces move most, unless
/// `watched_component` (0, 1, 2) names it (a beam's deflection u_y).
FrameTransientResult RunFrameTransient(const FrameModel& model, const FrameLoadCase& loads,
                                       const TransientOptions& options,
                                       const std::vector<FrameRecordPoint>& record,
                                       NonlinearForce* force = nullptr,
                                       const FrameDrives& drives = {}, int watched_component = -1);

}  // namespace cosmems
