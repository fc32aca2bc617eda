#pragma once

#include <cmath>

#include "cosmems/core/constants.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// The shape factors of the gas film under a rigid rectangular plate, a [m] along x by b along z,
/// at gap h over the substrate: the film resists the plate's motion with
///   F_y = -(mu / h^3) translation v_y,   M_z = -(mu / h^3) tilt_z omega_z,
///   M_x = -(mu / h^3) tilt_x omega_x
/// (the three decouple by the rectangle's symmetry). They solve Reynolds' equation for an
/// incompressible film of uniform thickness, lap(p) = 12 mu v(x, z) / h^3 with p = 0 along the
/// four edges (the gas escapes at ambient pressure), by its double sine series:
///   translation = 768 a b / pi^6 sum_{m, n odd} 1 / (m^2 n^2 (m^2/a^2 + n^2/b^2)),
///   tilt_z = 192 a^3 b / pi^6 sum_{m even, n odd} (same term),
///   tilt_x = 192 a b^3 / pi^6 sum_{m odd, n even} (same term).
/// The first is Blech's (1983) closed form at a vanishing squeeze number; a long plate's tends
/// to the strip's a b^3 (SqueezeFilm) and a square's is 0.4217 a^4. Like the strip's, the film
/// holds while the squeeze number 12 mu omega b^2 / (p_a h^2) stays well below 1. Each sum's inner
/// series, along the longer side, is summed in closed form (SumOverOdd, SumOverEven); the outer
/// one runs to index 4000, its tail falling as the inverse cube of the last index (below 1e-10).
struct PlateSqueezeFactors {
  double translation = 0.0;  ///< m^4
  double tilt_z = 0.0;       ///< m^6, about z (the lever along x)
  double tilt_x = 0.0;       ///< m^6, about x (the lever along z)

  static PlateSqueezeFactors Of(double a, double b) {
    RequirePositive("plate side a", a);
    RequirePositive("plate side b", b);
    const double pi6 = kPi * kPi * kPi * kPi * kPi * kPi;
    return {768.0 * a * b / pi6 * Sum(a, b, true, true),
            192.0 * a * a * a * b / pi6 * Sum(a, b, false, true),
            192.0 * a * b * b * b / pi6 * Sum(a, b, true, false)};
  }

 private:
  // sum over m (odd or even, from 1 or 2) and n alike of 1 / (m^2 n^2 (m^2/a^2 + n^2/b^2)).
  static double Sum(double a, double b, bool m_odd, bool n_odd) {
    if (a < b) return Sum(b, a, n_odd, m_odd);  // the term is symmetric in (m, a) and (n, b)
    double sum = 0.0;
    for (int n = n_odd ? 1 : 2; n < 4000; n += 2) {
      const double c = n * a / b;  // >= 1: the closed forms below lose no digits
      sum += a * a / (double(n) * n) * (m_odd ? SumOverOdd(c) : SumOverEven(c));
    }
    return sum;
  }
  // sum over odd m of 1 / (m^2 (m^2 + c^2)) = (pi^2/8 - pi tanh(pi c/2) / (4c)) / c^2, from
  // 1 / (x (x + c^2)) = (1/x - 1/(x + c^2)) / c^2 and the sums of 1/m^2 and 1/(m^2 + c^2).
  static double SumOverOdd(double c) {
    return (kPi * kPi / 8.0 - kPi * std::tanh(0.5 * kPi * c) / (4.0 * c)) / (c * c);
  }
  // sum over even m >= 2 of the same: (pi^2/24 - (pi c coth(pi c/2) - 2) / (4 c^2)) / c^2.
  static double SumOverEven(double c) {
    return (kPi * kPi / 24.0 - (kPi * c / std::tanh(0.5 * kPi * c) - 2.0) / (4.0 * c * c)) /
           (c * c);
  }
};

}  // namespace cosmems
