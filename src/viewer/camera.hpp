#pragma once

#include <Eigen/Core>

#include "viewport.hpp"

namespace cosmems::viewer {

/// A ray from the eye through a pixel, in world coordinates.
struct Ray {
  Eigen::Vector3d origin;
  Eigen::Vector3d direction;  ///< unit length
};

/// A perspective camera orbiting a target point: yaw about the world's y axis (the normal to the
/// substrate), pitch above the x-z plane, distance from the target. The display and the tests
/// use the same matrices, so a test can say where a world point lands on the screenshot.
class OrbitCamera {
 public:
  OrbitCamera(const Eigen::Vector3d& target, double distance, double yaw_rad, double pitch_rad);

  Eigen::Vector3d Eye() const;
  const Eigen::Vector3d& target() const { return target_; }
  double distance() const { return distance_; }
  /// World to eye coordinates (right-handed, looking down -z).
  Eigen::Matrix4d View() const;
  /// Eye to clip coordinates for a viewport of aspect `width / height`.
  Eigen::Matrix4d Projection(double aspect) const;

  /// Where `world` lands in `viewport` [pixels from the window's top-left corner, y down, as in
  /// an image file]; false when it is behind the eye.
  bool Project(const Eigen::Vector3d& world, const Viewport& viewport,
               Eigen::Vector2d& pixel) const;
  /// The ray through `pixel` (same convention as Project()).
  Ray Unproject(const Eigen::Vector2d& pixel, const Viewport& viewport) const;

  /// Turns the view by a mouse drag of `dx`, `dy` pixels; the pitch stays within +-89 degrees.
  void Orbit(double dx, double dy);
  /// Slides the target with the drag, by as much as the drag covers at the target's depth.
  void Pan(double dx, double dy, const Viewport& viewport);
  /// Moves toward the target (`steps` > 0) or away, 10 % of the distance a step.
  void Zoom(double steps);

 private:
  static constexpr double kFieldOfViewY = 0.6;  // rad, about 34 degrees

  Eigen::Vector3d target_;
  double distance_;
  double yaw_;
  double pitch_;
};

}  // namespace cosmems::viewer
