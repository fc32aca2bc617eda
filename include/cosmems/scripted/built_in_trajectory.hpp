#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "cosmems/scripted/trajectory.hpp"

namespace cosmems {

/// The geometry and timing shared by the built-in motions, in the device frame [m, s].
struct MotionShape {
  /// Where every motion starts and ends: a point above the structure, clear of contact.
  Eigen::Vector3d start_m = Eigen::Vector3d(0.0, 0.01, 0.0);
  double depth_m = 0.02;  ///< how far the tip descends along -y
  double sweep_m = 0.04;  ///< how far "sweep" travels along +x at depth
  double period_s = 2.0;  ///< one cycle of the motion
  int cycles = 3;         ///< cycles in the script; Duration() = cycles * period_s

  /// Throws std::invalid_argument naming the field and its value.
  void Validate() const;
};

/// The names MakeBuiltInTrajectory() accepts: "press", "sweep", "tap".
std::vector<std::string> BuiltInTrajectoryNames();

/// A built-in motion; every phase of it follows a raised-cosine profile (zero velocity at both
/// ends of the phase, bounded acceleration), so the script never asks the hand for an infinite
/// acceleration:
/// - "press": descend to depth (40 % of a period), hold (30 %), rise (30 %);
/// - "sweep": descend to depth (20 %), move along +x by sweep_m (30 %) and back (30 %), rise
///   (20 %);
/// - "tap": four quick press-release taps to depth per period, each a quarter period long: a
///   half-cosine down and up over its first half, a pause above the structure over the second.
/// Before the start and after the end the tip rests at shape.start_m. Throws
/// std::invalid_argument for an unknown name (listing the valid ones) or an invalid shape.
std::unique_ptr<Trajectory> MakeBuiltInTrajectory(const std::string& name,
                                                  const MotionShape& shape = {});

}  // namespace cosmems
