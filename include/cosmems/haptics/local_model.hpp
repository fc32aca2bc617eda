#pragma once

#include <Eigen/Core>
#include <algorithm>

namespace cosmems {

/// What the physics publishes for the servo loop (Cavusoglu & Tendick's multi-rate scheme): the
/// probe's force and a linear model of how it changes as the probe moves into the beam, so that a
/// servo loop faster than the physics renders a force that follows the hand between two updates.
/// Micro world, SI, beam axes.
struct LocalModel {
  Eigen::Vector3d probe_m = Eigen::Vector3d::Zero();  ///< where the physics placed the probe
  /// The outward normal of the face the probe touches or is nearest to: the force's direction.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double force_n = 0.0;            ///< the beam's push on the probe, along the normal (>= 0)
  double stiffness_n_per_m = 0.0;  ///< d(force)/d(depth): coupling and beam in series
  double clearance_m = 0.0;        ///< gap between probe and face when not touching (>= 0)
  double source_time_s = 0.0;      ///< device time of the probe position the physics used
  bool valid = false;              ///< false until the physics has run, or after it failed

  /// The force on the probe at `probe_now_m` [N], extrapolated from this model along the normal:
  /// unilateral, so never pulling, and zero until the probe has come through the clearance.
  Eigen::Vector3d ForceAt(const Eigen::Vector3d& probe_now_m) const {
    const double approach = normal.dot(probe_m - probe_now_m);
    return std::max(0.0, force_n + stiffness_n_per_m * (approach - clearance_m)) * normal;
  }
};

}  // namespace cosmems
