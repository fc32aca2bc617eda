#pragma once

// Exact natural frequencies of an Euler-Bernoulli space frame, for the mesh convergence of the
// frame model: each member's transcendental dynamic stiffness (bending in its two planes from
// sin, cos, sinh and cosh of beta L; axial and torsional waves from sin and cos), rotated into
// place and assembled as the oracle assembles its elements (frame_oracle.hpp), bodies adding
// -w^2 times their rigid mass, supports and rigid links imposed through the oracle's null-space
// basis. A frequency is the root of det D(w) next to a guess, found by bisection on the sign of
// the determinant: no discretisation at all, so the error of a mesh is measured, not estimated.

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

#include "cosmems/core/constants.hpp"
#include "frame_oracle.hpp"

namespace cosmems::test::oracle {
namespace detail {

/// Exact bending dynamic stiffness over (w_a, theta_a, w_b, theta_b), theta = +dw/dx, of a beam
/// of bending stiffness ei and mass per length rho_a at circular frequency w > 0.
inline Eigen::Matrix4d ExactBending(double ei, double rho_a, double l, double w) {
  const double beta = std::pow(rho_a * w * w / ei, 0.25);
  const double x = beta * l;
  const double c = std::cos(x), s = std::sin(x), ch = std::cosh(x), sh = std::sinh(x);
  const double delta = 1.0 - c * ch;
  const double k11 = ei * beta * beta * beta * (ch * s + sh * c) / delta;
  const double k12 = ei * beta * beta * sh * s / delta;
  const double k13 = -ei * beta * beta * beta * (sh + s) / delta;
  const double k14 = ei * beta * beta * (ch - c) / delta;
  const double k22 = ei * beta * (ch * s - sh * c) / delta;
  const double k24 = ei * beta * (sh - s) / delta;
  Eigen::Matrix4d k;
  k << k11, k12, k13, k14,   //
      k12, k22, -k14, k24,   //
      k13, -k14, k11, -k12,  //
      k14, k24, -k12, k22;
  return k;
}

/// Exact two-node dynamic stiffness of a rod (axial: stiffness EA, inertia rho A; torsion: GJ,
/// rho I_p), as the diagonal and off-diagonal entries.
inline Eigen::Vector2d ExactRod(double stiffness, double inertia, double l, double w) {
  const double a = w * std::sqrt(inertia / stiffness) * l;
  const double scale = stiffness / l * a / std::sin(a);
  return {scale * std::cos(a), -scale};
}

}  // namespace detail

/// The exact dynamic stiffness D(w) of `frame` (each member one exact element, whatever its
/// `elements`) reduced onto its free motions, Jacobi-scaled by its static stiffness D(0).
inline Eigen::MatrixXd ExactDynamicStiffness(const Frame& frame, double w) {
  Frame whole = frame;
  for (Member& m : whole.members) m.elements = 1;
  const detail::Reduced reduced(whole);  // nodes and bodies: no interior nodes
  const Eigen::Index n = reduced.model.k.rows();
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(n, n);
  for (const Member& mb : whole.members) {
    const Eigen::Vector3d& pa = frame.nodes[mb.a];
    const Eigen::Vector3d& pb = frame.nodes[mb.b];
    const double l = (pb - pa).norm();
    detail::Matrix12d k = detail::Matrix12d::Zero();
    const Eigen::Vector2d axial = detail::ExactRod(mb.young * mb.area, mb.density * mb.area, l, w);
    const Eigen::Vector2d twist = detail::ExactRod(mb.shear * mb.j, mb.density * mb.polar, l, w);
    detail::AddPair(k, 0, axial[0], axial[1]);
    detail::AddPair(k, 3, twist[0], twist[1]);
    const double rho_a = mb.density * mb.area;
    detail::AddBending(k, detail::ExactBending(mb.young * mb.iz, rho_a, l, w), 1, 5, 1);
    detail::AddBending(k, detail::ExactBending(mb.young * mb.iy, rho_a, l, w), 2, 4, -1);
    detail::Matrix12d t = detail::Matrix12d::Zero();
    const Eigen::Matrix3d r = detail::Axes(pa, pb, mb.up);
    for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = r;
    const detail::Matrix12d kg = t.transpose() * k * t;
    const int node[2] = {mb.a, mb.b};
    for (int i = 0; i < 2; ++i)
      for (int c = 0; c < 2; ++c)
        d.block<6, 6>(6 * node[i], 6 * node[c]) += kg.block<6, 6>(6 * i, 6 * c);
  }
  const int first_body = static_cast<int>(frame.nodes.size());
  for (std::size_t b = 0; b < frame.bodies.size(); ++b) {
    const int c = 6 * (first_body + static_cast<int>(b));
    d.block<3, 3>(c, c) -= w * w * frame.bodies[b].mass * Eigen::Matrix3d::Identity();
    d.block<3, 3>(c + 3, c + 3) -= w * w * frame.bodies[b].inertia;
  }
  const Eigen::MatrixXd& z = reduced.model.z;
  return reduced.s.asDiagonal() * (z.transpose() * d * z) * reduced.s.asDiagonal();
}

/// The sign of det D(w): the product of the signs of its eigenvalues (D is symmetric).
inline int ExactDeterminantSign(const Frame& frame, double w) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(ExactDynamicStiffness(frame, w),
                                                             Eigen::EigenvaluesOnly);
  int sign = 1;
  for (Eigen::Index i = 0; i < eigen.eigenvalues().size(); ++i) {
    if (eigen.eigenvalues()[i] < 0) sign = -sign;
  }
  return sign;
}

/// The exact natural frequency [Hz] next to `guess_hz` (within 1 %): the root of det D(w),
/// bracketed by widening steps from 1e-7 of the guess, then bisected to the last bit. The guess
/// must be closer to this root than to any other root or pole of det D.
inline double ExactFrequency(const Frame& frame, double guess_hz) {
  const double guess = 2 * kPi * guess_hz;
  const int at_guess = ExactDeterminantSign(frame, guess);
  double lo = guess, hi = guess;
  for (double inner = 0.0, step = 1e-7;; inner = step, step *= 2) {
    if (step > 1e-2) throw std::runtime_error("oracle: no root of det D(w) near the guess");
    if (ExactDeterminantSign(frame, guess * (1 - step)) != at_guess) {
      lo = guess * (1 - step);
      hi = guess * (1 - inner);
      break;
    }
    if (ExactDeterminantSign(frame, guess * (1 + step)) != at_guess) {
      lo = guess * (1 + inner);
      hi = guess * (1 + step);
      break;
    }
  }
  const int at_lo = ExactDeterminantSign(frame, lo);
  while (hi - lo > 4e-16 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (ExactDeterminantSign(frame, mid) == at_lo ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi) / (2 * kPi);
}

}  // namespace cosmems::test::oracle
