#pragma once

#include "cosmems/core/units.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/time/rayleigh_damping.hpp"

namespace cosmems {

/// Structural damping as a scene declares it, in SI: none, a quality factor Q (every mode
/// damped at zeta = 1/(2Q)), or Rayleigh coefficients alpha [1/s] and beta [s].
struct DampingModel {
  enum class Kind { kNone, kQualityFactor, kRayleigh };
  Kind kind = Kind::kNone;
  double quality_factor = 0.0;
  RayleighDamping rayleigh;  ///< SI

  static DampingModel QualityFactor(double q) {
    RequirePositive("effects.damping.quality_factor", q);
    return {Kind::kQualityFactor, q, {}};
  }
  static DampingModel Rayleigh(double alpha, double beta) {
    if (!(alpha >= 0.0) || !(beta >= 0.0) || !std::isfinite(alpha + beta)) {
      throw std::invalid_argument("effects.damping.rayleigh = [" + FormatValue(alpha) + ", " +
                                  FormatValue(beta) + "]: must be finite and non-negative");
    }
    return {Kind::kRayleigh, 0.0, {alpha, beta}};
  }

  /// The damping ratio of a mode at angular frequency omega [rad/s].
  double ModalRatio(double omega) const {
    switch (kind) {
      case Kind::kQualityFactor:
        return 0.5 / quality_factor;
      case Kind::kRayleigh:
        return rayleigh.DampingRatio(omega);
      case Kind::kNone:
        break;
    }
    return 0.0;
  }

  /// Rayleigh coefficients for a full (non-modal) model in internal units. A quality factor
  /// becomes the Rayleigh pair that damps the modes at w1 and w2 [rad/s] at exactly 1/(2Q).
  RayleighDamping ForFullModel(double w1, double w2, const UnitSystem& units) const {
    RayleighDamping si;
    if (kind == Kind::kRayleigh) si = rayleigh;
    if (kind == Kind::kQualityFactor)
      si = RayleighDamping::FromQualityFactor(quality_factor, w1, w2);
    return {si.mass * units.time, si.stiffness / units.time};
  }
};

}  // namespace cosmems
