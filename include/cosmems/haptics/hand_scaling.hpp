#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// The map between the hand's world (device frame, m and N) and the micro world (beam axes, m
/// and N). The axes coincide: device x right = along the beam, y up = away from the substrate,
/// z toward the user = across the width. A hand displacement of position_scale metres moves the
/// probe by one metre; a micro force of one newton is felt as force_scale newtons. The hand then
/// feels a micro stiffness k as k force_scale / position_scale (haptics-notes 4.6).
struct HandScaling {
  double position_scale = 1.0;                                ///< hand m per micro m
  double force_scale = 1.0;                                   ///< hand N per micro N
  Eigen::Vector3d device_origin_m = Eigen::Vector3d::Zero();  ///< device point of micro origin

  void Validate() const {
    RequirePositive("position_scale", position_scale);
    RequirePositive("force_scale", force_scale);
    if (!device_origin_m.allFinite()) {
      throw std::invalid_argument("device_origin_m is not finite");
    }
  }
  Eigen::Vector3d ToMicro(const Eigen::Vector3d& device_m) const {
    return (device_m - device_origin_m) / position_scale;
  }
  Eigen::Vector3d ToDevice(const Eigen::Vector3d& micro_m) const {
    return device_origin_m + micro_m * position_scale;
  }
  Eigen::Vector3d HandForce(const Eigen::Vector3d& micro_n) const { return micro_n * force_scale; }
  /// The stiffness the hand feels for a micro stiffness [N/m].
  double FeltStiffness(double micro_n_per_m) const {
    return micro_n_per_m * force_scale / position_scale;
  }
  /// The micro stiffness felt as `hand_n_per_m`.
  double MicroStiffness(double hand_n_per_m) const {
    return hand_n_per_m * position_scale / force_scale;
  }
};

}  // namespace cosmems
