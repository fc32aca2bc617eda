#pragma once

#include <Eigen/Core>
#include <array>

#include "cosmems/beam/frame_element.hpp"

namespace cosmems {

/// Values of the static (order-0) shape functions and their derivatives at a point of an
/// element: what loads are lumped with and what displacements, slopes and curvatures are
/// recovered from. Derivatives are with respect to xi; divide by l^k for d^k/dx^k.
struct ShapeValues {
  std::array<double, 2> bar{};        ///< linear: u1, u2
  std::array<double, 2> bar_slope{};  ///< d/dxi
  std::array<double, 4> bending{};    ///< Hermite: w1, l theta1, w2, l theta2
  std::array<double, 4> bending_slope{};
  std::array<double, 4> bending_curvature{};

  static ShapeValues At(const FrameBases& bases, double xi) {
    ShapeValues v;
    for (int a = 0; a < 2; ++a) {
      const internal::Polynomial& n = bases.bar.Shape(0, a);
      v.bar[a] = internal::Evaluate(n, xi);
      v.bar_slope[a] = internal::Evaluate(internal::Derivative(n), xi);
    }
    for (int a = 0; a < 4; ++a) {
      const internal::Polynomial& n = bases.bending.Shape(0, a);
      const internal::Polynomial d1 = internal::Derivative(n);
      v.bending[a] = internal::Evaluate(n, xi);
      v.bending_slope[a] = internal::Evaluate(d1, xi);
      v.bending_curvature[a] = internal::Evaluate(internal::Derivative(d1), xi);
    }
    return v;
  }
};

}  // namespace cosmems
