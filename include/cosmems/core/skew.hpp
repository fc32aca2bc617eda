#pragma once

#include <Eigen/Core>

namespace cosmems {

/// [v]x, the matrix of the cross product: Skew(a) b = a x b.
inline Eigen::Matrix3d Skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s(0, 0) = s(1, 1) = s(2, 2) = 0.0;
  s(0, 1) = -v.z();
  s(1, 0) = v.z();
  s(0, 2) = v.y();
  s(2, 0) = -v.y();
  s(1, 2) = -v.x();
  s(2, 1) = v.x();
  return s;
}

}  // namespace cosmems
