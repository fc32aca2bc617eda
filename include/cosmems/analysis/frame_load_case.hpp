#pragma once

#include <Eigen/Core>
#include <vector>

namespace cosmems {

/// A force and a moment at a node of a frame, at a body's centre or at a point along a member,
/// in SI, global axes.
struct FramePointLoad {
  int node = -1;                                     ///< a description node, or -1
  int body = -1;                                     ///< a body (at its centre), when node is -1
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< N
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< N m
  int member = -1;  ///< a member, when node and body are -1: the load at the fraction `at` along it
  double at = 0.0;  ///< 0 at the member's first node, 1 at its second
};

/// Static loads on a frame, in SI.
struct FrameLoadCase {
  std::vector<FramePointLoad> points;
  Eigen::Vector3d distributed = Eigen::Vector3d::Zero();  ///< N/m on every member, global axes
};

}  // namespace cosmems
