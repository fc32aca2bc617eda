#include "camera.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace cosmems::viewer {
namespace {

constexpr double kMaxPitch = 89.0 * M_PI / 180.0;
constexpr double kRadiansPerPixel = 0.006;

}  // namespace

OrbitCamera::OrbitCamera(const Eigen::Vector3d& target, double distance, double yaw_rad,
                         double pitch_rad)
    : target_(target),
      distance_(distance),
      yaw_(yaw_rad),
      pitch_(std::clamp(pitch_rad, -kMaxPitch, kMaxPitch)) {}

Eigen::Vector3d OrbitCamera::Eye() const {
  const Eigen::Vector3d from_target(std::cos(pitch_) * std::sin(yaw_), std::sin(pitch_),
                                    std::cos(pitch_) * std::cos(yaw_));
  return target_ + distance_ * from_target;
}

Eigen::Matrix4d OrbitCamera::View() const {
  const Eigen::Vector3d eye = Eye();
  const Eigen::Vector3d back = (eye - target_).normalized();
  const Eigen::Vector3d right = Eigen::Vector3d::UnitY().cross(back).normalized();
  const Eigen::Vector3d up = back.cross(right);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = right.transpose();
  view.block<1, 3>(1, 0) = up.transpose();
  view.block<1, 3>(2, 0) = back.transpose();
  view(0, 3) = -right.dot(eye);
  view(1, 3) = -up.dot(eye);
  view(2, 3) = -back.dot(eye);
  return view;
}

Eigen::Matrix4d OrbitCamera::Projection(double aspect) const {
  // The near plane close enough to zoom onto a 2 um beam, the far one past the whole stage.
  const double near = 0.01 * distance_, far = 100.0 * distance_;
  const double f = 1.0 / std::tan(0.5 * kFieldOfViewY);
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (far + near) / (near - far);
  p(2, 3) = 2.0 * far * near / (near - far);
  p(3, 2) = -1.0;
  return p;
}

bool OrbitCamera::Project(const Eigen::Vector3d& world, const Viewport& viewport,
                          Eigen::Vector2d& pixel) const {
  const Eigen::Vector4d clip =
      Projection(viewport.Aspect()) * View() * Eigen::Vector4d(world.x(), world.y(), world.z(), 1);
  if (clip.w() <= 0.0) return false;
  const double ndc_x = clip.x() / clip.w(), ndc_y = clip.y() / clip.w();
  pixel.x() = viewport.x + 0.5 * (ndc_x + 1.0) * viewport.width;
  pixel.y() = viewport.y + 0.5 * (1.0 - ndc_y) * viewport.height;
  return true;
}

Ray OrbitCamera::Unproject(const Eigen::Vector2d& pixel, const Viewport& viewport) const {
  const double ndc_x = 2.0 * (pixel.x() - viewport.x) / viewport.width - 1.0;
  const double ndc_y = 1.0 - 2.0 * (pixel.y() - viewport.y) / viewport.height;
  const double f = 1.0 / std::tan(0.5 * kFieldOfViewY);
  const Eigen::Vector3d eye_direction(ndc_x * viewport.Aspect() / f, ndc_y / f, -1.0);
  const Eigen::Matrix3d to_world = View().block<3, 3>(0, 0).transpose();
  return Ray{Eye(), (to_world * eye_direction).normalized()};
}

void OrbitCamera::Orbit(double dx, double dy) {
  yaw_ -= kRadiansPerPixel * dx;
  pitch_ = std::clamp(pitch_ + kRadiansPerPixel * dy, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::Pan(double dx, double dy, const Viewport& viewport) {
  const double world_per_pixel = 2.0 * distance_ * std::tan(0.5 * kFieldOfViewY) / viewport.height;
  const Eigen::Matrix4d view = View();
  const Eigen::Vector3d right = view.block<1, 3>(0, 0).transpose();
  const Eigen::Vector3d up = view.block<1, 3>(1, 0).transpose();
  target_ += world_per_pixel * (-dx * right + dy * up);
}

void OrbitCamera::Zoom(double steps) { distance_ *= std::pow(0.9, steps); }

}  // namespace cosmems::viewer
