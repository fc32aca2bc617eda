#pragma once

#include <Eigen/Core>
#include <vector>

namespace cosmems {

/// A force and a moment applied at a point of the beam axis, in SI.
struct PointLoad {
  double x = 0.0;                                    ///< m from the first node
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< N; -y pushes toward the substrate
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< N m, right-handed about x, y, z
};

/// Static loads on a beam, in SI. Loads on supported degrees of freedom become reactions.
struct LoadCase {
  std::vector<PointLoad> points;
  Eigen::Vector3d distributed = Eigen::Vector3d::Zero();  ///< N/m, uniform over the whole length

  bool Empty() const { return points.empty() && distributed.isZero(0.0); }
};

}  // namespace cosmems
