#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/analysis/comb_drive.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/frame_transient_analysis.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// One comb drive at its static equilibrium.
struct CombDriveState {
  double force_n = 0.0;        ///< the engagement force along its direction
  double engagement_m = 0.0;   ///< its body's centre moved along its direction
  double offset_m = 0.0;       ///< and across its fingers
  double capacitance_f = 0.0;  ///< there
  /// the comb's voltage at the side instability: every comb's voltage scaled by one factor
  /// until the suspension no longer holds the bodies across their fingers (infinity when no
  /// factor up to 1e6 reaches it)
  double side_instability_voltage_v = std::numeric_limits<double>::infinity();
};

/// A device's statics with its comb drives: the frame's statics under the scene's loads and
/// every comb's pull, each comb's state, and where the combs give way sideways.
struct CombDriveSolution {
  FrameStaticSolution statics;
  std::vector<CombDriveState> combs;
  /// the factor of every comb's voltage at the side instability (infinity: none up to 1e6)
  double side_instability_factor = std::numeric_limits<double>::infinity();
  /// the last stable state found below that factor, the combs' voltages scaled by
  /// `last_stable_factor` (when the factor is finite)
  FrameStaticSolution last_stable;
  double last_stable_factor = 0.0;
  int solves = 0;  ///< the factors tried on the way to the instability
};

/// The statics of a device driven by comb drives (each pulling at its body's centre), and the
/// side instability of the combs together: every comb's voltage scaled by one factor, the
/// scene's loads and every other force held, until the suspension no longer holds the bodies
/// across their fingers. When every comb is at 0 V the factor scales 1 V on each. With no other
/// force (`forces` and `pressures` empty) the statics are linear and the combs' forces loads,
/// the instability in closed form (internal::SolveLinearCombDrives); otherwise the combs are a
/// CombDriveForce in Newton's statics beside `forces`, ramped with the loads together with the
/// `pressures` across the gap (SolveFrameNonlinearStatic), and the instability is bisected on
/// the tangent's definiteness. Statuses as SolveFrameStatic's and SolveFrameNonlinearStatic's.
CombDriveSolution SolveCombDrives(const FrameModel& model, const FrameLoadCase& loads,
                                  const std::vector<CombDrive>& combs,
                                  const std::vector<FrameElementForce*>& forces = {},
                                  const std::vector<FrameElementForce*>& pressures = {});

/// The comb drives of a frame's transient: each comb's engagement force at 1 V at its body's
/// centre, a pattern the run scales by the square of the comb's voltage in time. Centred, the
/// force does not depend on the engagement, so the drive is a load and a comb-driven resonator
/// keeps the linear step; the negative stiffness across the fingers, which matters near the side
/// instability SolveCombDrives reports, is left out.
FrameDrives CombDriveLoads(const FrameModel& model, const std::vector<CombDrive>& combs);

}  // namespace cosmems
