#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace cosmems {

/// What the physics publishes for the servo loop (Cavusoglu & Tendick's multi-rate scheme): the
/// probe's force and a linear model of how it changes as the probe moves down, so that a servo
/// loop faster than the physics renders a force that follows the hand between two updates.
/// Micro world, SI, beam axes.
struct LocalModel {
  Eigen::Vector3d probe_m = Eigen::Vector3d::Zero();  ///< where the physics placed the probe
  double force_n = 0.0;            ///< the beam's push on the probe, along +y (>= 0)
  double stiffness_n_per_m = 0.0;  ///< d(force)/d(depth): coupling and beam in series
  double clearance_m = 0.0;        ///< gap between probe and beam face when not touching (>= 0)
  double source_time_s = 0.0;      ///< device time of the probe position the physics used
  bool valid = false;              ///< false until the physics has run, or after it failed

  /// The force on the probe at `probe_m` [N, +y], extrapolated from this model: unilateral, so
  /// never pulling, and zero until the probe has come down through the clearance.
  double ForceAt(const Eigen::Vector3d& probe_now_m) const {
    const double descent = probe_m.y() - probe_now_m.y();
    return std::max(0.0, force_n + stiffness_n_per_m * (descent - clearance_m));
  }
};

}  // namespace cosmems
