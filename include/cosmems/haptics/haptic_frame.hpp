#pragma once

#include <Eigen/Core>

#include "cosmems/core/status.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems {

/// What the display side shows of one physics tick (published at the physics rate, read at
/// 30 Hz through a TripleBuffer). Sized once by HapticPhysics::MakeFrame(); filling it allocates
/// nothing.
struct HapticFrame {
  double time_s = 0.0;                                      ///< simulated time
  Eigen::Vector3d probe_m = Eigen::Vector3d::Zero();        ///< probe centre, global axes
  Eigen::Vector3d probe_force_n = Eigen::Vector3d::Zero();  ///< the structure's push on it
  /// The structure's motion, one column per carrier of its FrameMesh: u [m] then theta [rad]
  /// about the carrier's reference point, global axes.
  Eigen::Matrix<double, 6, Eigen::Dynamic> carrier_motion_m;
  ContactSummary contact;       ///< with the substrate
  ContactEvents events;         ///< counted since the start
  Status status = Status::kOk;  ///< of the tick's physics
};

}  // namespace cosmems
