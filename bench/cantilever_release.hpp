#pragma once

// An independent oracle for the release transient: the tip of an Euler-Bernoulli cantilever let
// go at t = 0, at rest in its static shape under a tip force, as the sum of its exact modes.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "cosmems/core/constants.hpp"

namespace cosmems::bench {

/// The released cantilever's tip deflection as a fraction of its static value w0:
///   w(L, t) / w0 = sum_n (12 / x_n^4) cos(x_n^2 t / tau),   tau = L^2 sqrt(rho A / EI),
/// x_n the roots of cos x cosh x = -1. The static shape expands in the mass-normalised modes as
/// w0(x) = P sum_n phi_n(L) phi_n(x) / w_n^2 (the modal load of a tip force P is P phi_n(L)), every
/// cantilever mode has phi_n(L)^2 = 4 / (rho A L), and w_n^2 = x_n^4 EI / (rho A L^4),
/// w0(L) = P L^3 / 3EI; hence the weights 12 / x_n^4, which sum to 1. The construction checks that
/// sum: the first `terms` weights must reach it within 1e-9 (the tail beyond n is about
/// 0.04 / n^3), which also bounds what the truncation leaves in any w(L, t).
class CantileverRelease {
 public:
  explicit CantileverRelease(double tau, int terms = 1000) {
    double sum = 0.0;
    for (int n = 1; n <= terms; ++n) {
      const double x = Root(n);
      weights_.push_back(12.0 / (x * x * x * x));
      omegas_.push_back(x * x / tau);
      sum += weights_.back();
    }
    if (!(std::abs(sum - 1.0) < 1e-9)) {
      std::fprintf(stderr, "CantileverRelease: the modal weights sum to %.15f, not 1\n", sum);
      std::abort();
    }
  }

  /// w(L, t) / w0 at t [s].
  double TipRatio(double t) const {
    double sum = 0.0;
    for (std::size_t n = 0; n < weights_.size(); ++n) sum += weights_[n] * std::cos(omegas_[n] * t);
    return sum;
  }

 private:
  // The n-th root of cos x + 1 / cosh x = 0 (cos x cosh x = -1 without overflowing cosh) by
  // Newton from (2n - 1) pi / 2, which it approaches as e^-x.
  static double Root(int n) {
    double x = (2 * n - 1) * kPi / 2;
    for (int i = 0; i < 50; ++i) {
      const double sech = 1.0 / std::cosh(x);
      const double step = (std::cos(x) + sech) / (-std::sin(x) - std::tanh(x) * sech);
      x -= step;
      if (std::abs(step) <= 1e-16 * x) break;
    }
    return x;
  }

  std::vector<double> weights_;
  std::vector<double> omegas_;  ///< rad/s
};

}  // namespace cosmems::bench
