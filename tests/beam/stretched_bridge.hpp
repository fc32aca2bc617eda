#pragma once

// An independent oracle for mid-plane stretching: the clamped-clamped beam under a uniform load,
// solved in closed form for a given tension, the tension found by bisection.

#include <algorithm>
#include <cmath>

namespace cosmems::test {

struct StretchedBridge {
  double tension = 0.0;  ///< N, N0 included
  double midspan = 0.0;  ///< m, along the load
};

/// The bridge of length l, bending stiffness ei and axial stiffness ea under a uniform load q
/// (N/m) with residual tension n0. At a tension N (k^2 = N / EI), with xi = x - L/2:
/// w = A + B cosh(k xi) - q xi^2 / (2N), B = q L / (2 N k sinh(k L/2)),
/// A = q L^2 / (8N) - B cosh(k L/2). Its stretching s(N) = 1/2 int w'^2 by Simpson's rule on 4000
/// intervals (error ~1e-13 relative); the tension solves N = N0 + EA s(N) / L by bisection.
inline StretchedBridge SolveStretchedBridge(double l, double ei, double ea, double q, double n0) {
  auto solution = [&](double n, double& midspan) {
    const double k = std::sqrt(n / ei);
    const double b = q * l / (2 * n * k * std::sinh(k * l / 2));
    const double a = q * l * l / (8 * n) - b * std::cosh(k * l / 2);
    midspan = a + b;
    const int intervals = 4000;
    double sum = 0.0;
    for (int i = 0; i <= intervals; ++i) {
      const double xi = -l / 2 + l * i / intervals;
      const double slope = b * k * std::sinh(k * xi) - q * xi / n;
      const double weight = (i == 0 || i == intervals) ? 1 : (i % 2 ? 4 : 2);
      sum += weight * slope * slope;
    }
    return 0.5 * sum * (l / intervals) / 3;
  };
  double lo = std::max(n0, 1e-12 * ea), hi = ea;
  double midspan = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid - n0 - ea * solution(mid, midspan) / l < 0 ? lo : hi) = mid;
  }
  const double n = 0.5 * (lo + hi);
  solution(n, midspan);
  return {n, midspan};
}

}  // namespace cosmems::test
