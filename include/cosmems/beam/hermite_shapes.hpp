#pragma once

#include <array>

namespace cosmems {

/// The Hermite cubics of w1, h theta1, w2, h theta2 at xi in [0, 1] of an element of length h:
/// the static (order-0) shape functions of u_y, what point forces and pressures are lumped with.
inline std::array<double, 4> HermiteShapes(double xi) {
  const double x2 = xi * xi, x3 = x2 * xi;
  return {1.0 - 3.0 * x2 + 2.0 * x3, xi - 2.0 * x2 + x3, 3.0 * x2 - 2.0 * x3, x3 - x2};
}

}  // namespace cosmems
