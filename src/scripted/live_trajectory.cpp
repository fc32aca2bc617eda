#include "cosmems/scripted/live_trajectory.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosmems {

LiveTrajectory::LiveTrajectory(const Eigen::Vector3d& start_m, double duration_s)
    : targets_(start_m), duration_s_(duration_s) {
  if (!start_m.allFinite()) throw std::invalid_argument("live trajectory: start_m is not finite");
  if (!(std::isfinite(duration_s) && duration_s > 0.0)) {
    throw std::invalid_argument("live trajectory: duration_s = " + std::to_string(duration_s) +
                                " must be finite and > 0");
  }
}

Eigen::Vector3d LiveTrajectory::Position(double /*t_s*/) const {
  targets_.Update();
  return targets_.Front();
}

}  // namespace cosmems
