#pragma once

#include <cmath>
#include <vector>

#include "cosmems/core/constants.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// An n-point Gauss-Legendre rule on [0, 1]: exact for polynomials of degree 2n - 1.
struct GaussLegendre {
  std::vector<double> points;
  std::vector<double> weights;  ///< summing to 1

  /// The rule of `n` points (1 ... 64): each root of P_n by Newton's method from Tricomi's
  /// estimate cos(pi (i + 3/4) / (n + 1/2)), which converges to round-off in a few iterations.
  static GaussLegendre Of(int n) {
    RequireWithin("quadrature points", n, 1, 64);
    GaussLegendre rule;
    rule.points.resize(n);
    rule.weights.resize(n);
    for (int i = 0; i < n; ++i) {
      double x = std::cos(kPi * (i + 0.75) / (n + 0.5));
      double slope = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        // P_n(x) and P_n'(x) by the three-term recurrence.
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        slope = n * (x * p1 - p0) / (x * x - 1.0);
        const double dx = p1 / slope;
        x -= dx;
        if (std::abs(dx) < 1e-16) break;
      }
      rule.points[i] = 0.5 * (1.0 - x);  // ascending on [0, 1]
      rule.weights[i] = 1.0 / ((1.0 - x * x) * slope * slope);
    }
    return rule;
  }
};

}  // namespace cosmems
