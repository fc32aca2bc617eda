#include "normal_quantile.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosmems::internal {

double NormalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

double NormalQuantile(double p) {
  if (!(p > 0.0 && p < 1.0)) {
    throw std::invalid_argument("normal quantile of " + std::to_string(p) + ": outside (0, 1)");
  }
  // The upper half by symmetry, so that the refinement works on the small tail probability.
  if (p > 0.5) return -NormalQuantile(1.0 - p);
  const double t = std::sqrt(-2.0 * std::log(p));
  double x = -(t - (2.515517 + t * (0.802853 + t * 0.010328)) /
                       (1.0 + t * (1.432788 + t * (0.189269 + t * 0.001308))));
  // Halley on Phi(x) - p: cubic convergence from 4.5e-4 takes three steps to round-off.
  const double root_two_pi = std::sqrt(2.0 * 3.14159265358979323846);
  for (int step = 0; step < 3; ++step) {
    const double u = (NormalCdf(x) - p) * root_two_pi * std::exp(0.5 * x * x);
    x -= u / (1.0 + 0.5 * x * u);
  }
  return x;
}

}  // namespace cosmems::internal
