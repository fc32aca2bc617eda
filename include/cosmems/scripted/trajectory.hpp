#pragma once

#include <Eigen/Core>

namespace cosmems {

/// Where a scripted hand holds the stylus tip over time, in the device frame (OpenHaptics' axes:
/// x right, y up, z toward the user) [m]. The scripted device samples it once per servo tick on
/// its servo thread, so Position() must not allocate, lock or throw (the tick is noexcept: a
/// throw ends the program). A non-finite position is allowed: it reaches the device state
/// unchanged, which is how tests feed the safety layer a broken sensor.
class Trajectory {
 public:
  virtual ~Trajectory() = default;

  /// The tip position at `t_s` seconds after the start of the script [m].
  virtual Eigen::Vector3d Position(double t_s) const = 0;
  /// Length of the script [s]: the device ticks over [0, Duration()] and then stops.
  virtual double Duration() const = 0;
};

}  // namespace cosmems
