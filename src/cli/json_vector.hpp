#pragma once

#include <Eigen/Core>
#include <vector>

namespace cosmems::internal {

/// A vector as a JSON array. + 0.0 turns -0 (a rotation the sign convention negates from zero,
/// say) into 0.
inline std::vector<double> ToJson(const Eigen::Vector3d& v) {
  return {v.x() + 0.0, v.y() + 0.0, v.z() + 0.0};
}

}  // namespace cosmems::internal
