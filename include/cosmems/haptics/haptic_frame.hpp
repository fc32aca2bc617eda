#pragma once

#include <Eigen/Core>

#include "cosmems/core/status.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems {

/// What the display side shows of one physics tick (published at the physics rate, read at
/// 30 Hz through a TripleBuffer). Sized once by HapticBeam::MakeFrame(); filling it allocates
/// nothing.
struct HapticFrame {
  double time_s = 0.0;                                      ///< simulated time
  Eigen::Vector3d probe_m = Eigen::Vector3d::Zero();        ///< probe centre, beam axes
  Eigen::Vector3d probe_force_n = Eigen::Vector3d::Zero();  ///< the beam's push on the probe
  Eigen::VectorXd node_x_m;                                 ///< node positions along the axis
  Eigen::VectorXd deflection_m;                             ///< u_y at each node
  Eigen::VectorXd rotation_rad;                             ///< theta_z (slope) at each node
  ContactSummary contact;                                   ///< with the substrate
  ContactEvents events;                                     ///< counted since the start
  Status status = Status::kOk;                              ///< of the tick's physics
};

}  // namespace cosmems
