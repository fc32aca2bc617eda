#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "cosmems/core/constants.hpp"
#include "cosmems/core/skew.hpp"

namespace cosmems {

// The rotation group SO(3) through unit quaternions. A rod's director frame is d_k = R e_k with
// R = R(q); rotations compose by quaternion products, so no angle ever wraps and no Euler-angle
// singularity exists. q and -q are the same rotation (the double cover): every function here
// gives the same answer for both.

/// The exponential map: the unit quaternion (cos(|theta|/2), sin(|theta|/2) theta/|theta|) of the
/// rotation by the angle |theta| [rad] about theta (right-handed), for any |theta|.
inline Eigen::Quaterniond QuaternionExp(const Eigen::Vector3d& theta) {
  const double angle = theta.norm();
  const double half = 0.5 * angle;
  // Both unconditionally, so that the compiler makes them one sincos call (a Newton update
  // takes one exponential per node).
  const double sine = std::sin(half);
  const double cosine = std::cos(half);
  // sin(half) / angle, by its series where the quotient would lose digits (error < 1e-20).
  const double k = angle < 1e-4 ? 0.5 * (1.0 - half * half / 6.0) : sine / angle;
  Eigen::Quaterniond q;
  q.w() = cosine;
  q.vec() = k * theta;
  return q;
}

namespace internal {

/// asin(s) / s for 0 <= s <= 1, by its series below s = 1e-2 (error < 1e-19).
inline double AsinOverArgument(double s) {
  if (s < 1e-2) {
    const double s2 = s * s;
    return 1.0 + s2 * (1.0 / 6.0 + s2 * (3.0 / 40.0 + s2 * 5.0 / 112.0));
  }
  return std::asin(s) / s;
}

}  // namespace internal

/// The logarithm: the rotation vector theta of q with |theta| <= pi [rad]. q and -q give the same
/// theta. q must be a unit quaternion.
inline Eigen::Vector3d QuaternionLog(const Eigen::Quaterniond& q) {
  const double sign = q.w() < 0.0 ? -1.0 : 1.0;
  const double s = q.vec().norm();  // sin(|theta|/2)
  const double w = sign * q.w();    // cos(|theta|/2) >= 0
  // 2 atan2(s, w) / s: near the identity through asin(s)/s, which stays accurate there.
  const double k = s < 0.5 ? 2.0 * internal::AsinOverArgument(s) : 2.0 * std::atan2(s, w) / s;
  return sign * k * q.vec();
}

/// The rotation vector of q on the branch nearest `reference`: among (phi + 2 pi k) n, with phi n
/// the principal rotation vector, the one closest to `reference` [rad]. Lifting node after node
/// along a rod this way gives a rotation vector that grows through pi, 2 pi, ... (2 pi for a rod
/// rolled into a full circle) instead of wrapping.
inline Eigen::Vector3d RotationVectorNear(const Eigen::Quaterniond& q,
                                          const Eigen::Vector3d& reference) {
  const Eigen::Vector3d principal = QuaternionLog(q);
  const double phi = principal.norm();
  constexpr double kTwoPi = 2.0 * kPi;
  if (phi < 1e-12) {  // the identity: the candidates are 2 pi k along any axis
    const double r = reference.norm();
    if (r < kPi) return principal;
    return std::round(r / kTwoPi) * kTwoPi * (reference / r) + principal;
  }
  const Eigen::Vector3d axis = principal / phi;
  const double k = std::round((reference.dot(axis) - phi) / kTwoPi);
  return (phi + kTwoPi * k) * axis;
}

/// The left Jacobian of the exponential map: exp((theta + delta)^) = exp((J_l(theta) delta)^)
/// exp(theta^) + O(|delta|^2), so J_l maps a change of the rotation vector to the spatial spin.
/// J_l = I + (1 - cos phi)/phi^2 [theta]x + (phi - sin phi)/phi^3 [theta]x^2, phi = |theta|.
inline Eigen::Matrix3d LeftJacobian(const Eigen::Vector3d& theta) {
  const double phi2 = theta.squaredNorm();
  const double phi = std::sqrt(phi2);
  double a = 0.0;
  double b = 0.0;
  if (phi < 1e-3) {  // series: the closed forms cancel catastrophically here (error < 1e-16)
    a = 0.5 - phi2 / 24.0 + phi2 * phi2 / 720.0;
    b = 1.0 / 6.0 - phi2 / 120.0 + phi2 * phi2 / 5040.0;
  } else {
    a = (1.0 - std::cos(phi)) / phi2;
    b = (phi - std::sin(phi)) / (phi2 * phi);
  }
  const Eigen::Matrix3d s = Skew(theta);
  return Eigen::Matrix3d::Identity() + a * s + b * s * s;
}

/// J_l(theta)^-1 = I - [theta]x / 2 + (1/phi^2 - (1 + cos phi) / (2 phi sin phi)) [theta]x^2, for
/// |theta| < 2 pi. The right Jacobian's inverse is J_r^-1(theta) = J_l^-1(-theta).
inline Eigen::Matrix3d LeftJacobianInverse(const Eigen::Vector3d& theta) {
  const double phi2 = theta.squaredNorm();
  const double phi = std::sqrt(phi2);
  const double c = phi < 1e-3 ? 1.0 / 12.0 + phi2 / 720.0 + phi2 * phi2 / 30240.0
                              : 1.0 / phi2 - (1.0 + std::cos(phi)) / (2.0 * phi * std::sin(phi));
  const Eigen::Matrix3d s = Skew(theta);
  return Eigen::Matrix3d::Identity() - 0.5 * s + c * s * s;
}

}  // namespace cosmems
