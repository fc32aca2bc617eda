#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "cosmems/core/skew.hpp"

namespace cosmems {

/// The local axes of a member from `from` to `to` as the rows of a rotation (local = R global):
/// x along the member, y its thickness direction (the given direction made normal to x), z
/// across its width, x cross y.
inline Eigen::Matrix3d MemberAxes(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                  const Eigen::Vector3d& thickness_direction) {
  const Eigen::Vector3d x = (to - from).normalized();
  const Eigen::Vector3d y = (thickness_direction - thickness_direction.dot(x) * x).normalized();
  Eigen::Matrix3d axes;
  axes.row(0) = x.transpose();
  axes.row(1) = y.transpose();
  axes.row(2) = x.cross(y).transpose();
  return axes;
}

}  // namespace cosmems
