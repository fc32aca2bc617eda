#pragma once

#include <cmath>
#include <string>

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// The generalised-alpha family (Chung & Hulbert 1993), which holds every integrator of the
/// Newmark family: the balance
///   M a_(n+1-am) + C v_(n+1-af) + K d_(n+1-af) = f(t_(n+1-af)),  x_(n+1-a) = (1-a) x_(n+1) + a
///   x_n,
/// closed by Newmark's updates
///   d_(n+1) = d_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_(n+1)),
///   v_(n+1) = v_n + dt ((1 - gamma) a_n + gamma a_(n+1)).
struct GeneralizedAlphaParameters {
  double alpha_m = 0.0;
  double alpha_f = 0.0;
  double beta = 0.25;
  double gamma = 0.5;

  /// Newmark-beta; (1/4, 1/2) is the average-acceleration rule (unconditionally stable, no
  /// numerical damping), (1/6, 1/2) linear acceleration, (0, 1/2) central difference.
  static GeneralizedAlphaParameters Newmark(double beta, double gamma) {
    RequireWithin("beta", beta, 0.0, 0.5);
    RequireWithin("gamma", gamma, 0.5, 1.0);
    return {0.0, 0.0, beta, gamma};
  }

  static GeneralizedAlphaParameters CentralDifference() { return {0.0, 0.0, 0.0, 0.5}; }

  /// Hilber-Hughes-Taylor with alpha in [0, 1/3] (alpha = 0 is average acceleration), written
  /// with the weight on the old state (Hilber's alpha is minus this): beta = (1 + alpha)^2 / 4,
  /// gamma = 1/2 + alpha; spectral radius at infinity (1 - alpha) / (1 + alpha).
  static GeneralizedAlphaParameters Hht(double alpha) {
    RequireWithin("alpha", alpha, 0.0, 1.0 / 3.0);
    return {0.0, alpha, 0.25 * (1.0 + alpha) * (1.0 + alpha), 0.5 + alpha};
  }

  /// Generalised-alpha with spectral radius rho_inf in [0, 1] at infinite frequency: the
  /// optimal high-frequency dissipation for second-order accuracy.
  static GeneralizedAlphaParameters FromSpectralRadius(double rho_inf) {
    RequireWithin("rho_inf", rho_inf, 0.0, 1.0);
    const double am = (2.0 * rho_inf - 1.0) / (rho_inf + 1.0);
    const double af = rho_inf / (rho_inf + 1.0);
    const double g = 0.5 - am + af;
    return {am, af, 0.25 * (1.0 - am + af) * (1.0 - am + af), g};
  }

  /// Explicit when beta = 0: the step needs only the mass (and damping) matrix.
  bool IsExplicit() const { return beta == 0.0; }
};

}  // namespace cosmems
