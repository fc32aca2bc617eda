#pragma once

#include <cmath>

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Proportional damping C = mass * M + stiffness * K, in the units of the model it acts on
/// (1/time and time). Modal damping ratio zeta(w) = mass / (2 w) + stiffness * w / 2.
struct RayleighDamping {
  double mass = 0.0;
  double stiffness = 0.0;

  double DampingRatio(double omega) const { return 0.5 * mass / omega + 0.5 * stiffness * omega; }

  /// The pair that gives zeta = 1 / (2 Q) at both angular frequencies w1 < w2 (typically the
  /// first two modes); modes between them are damped slightly less, modes above more.
  static RayleighDamping FromQualityFactor(double quality_factor, double w1, double w2) {
    RequirePositive("quality_factor", quality_factor);
    const double zeta = 0.5 / quality_factor;
    return {2.0 * zeta * w1 * w2 / (w1 + w2), 2.0 * zeta / (w1 + w2)};
  }
};

}  // namespace cosmems
