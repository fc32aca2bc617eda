#pragma once

#include <Eigen/Core>

namespace cosmems {

/// One recorded servo tick of a ScriptedDevice, device frame, SI.
struct ScriptedSample {
  double time_s = 0.0;  ///< tick / rate
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  Eigen::Vector3d force_n = Eigen::Vector3d::Zero();  ///< what the safety layer let through
};

}  // namespace cosmems
