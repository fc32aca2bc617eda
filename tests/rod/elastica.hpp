#pragma once

// Independent oracles for the Cosserat rod: the planar elastica of an inextensible, unshearable
// cantilever of length 1, solved by shooting.

#include <cmath>

namespace cosmems::test {

/// The tip of a cantilever elastica, as fractions of the length.
struct ElasticaTip {
  double shortening = 0.0;  ///< 1 - x_tip / L: the horizontal displacement toward the root
  double deflection = 0.0;  ///< -y_tip / L: the vertical displacement along the load
  double angle = 0.0;       ///< theta(L) [rad], the tip's rotation toward the load
};

/// The cantilever elastica under a tip force P of direction (-sin beta, -cos beta) (beta = 0:
/// straight down), alpha = P L^2 / EI. With theta the tangent's angle below the x axis,
/// EI theta' is the bending moment, so theta'' = -alpha cos(theta - beta) with theta(0) = 0
/// (clamped) and theta'(1) = 0 (no moment at the tip). Shooting: RK4 over 4000 steps (global
/// error ~1e-14) for theta, theta', x, y, and bisection on theta'(0) in [0, alpha], where
/// theta'(1) changes sign (theta'(0) = alpha times the moment arm, which lies in [0, 1]).
inline ElasticaTip Elastica(double alpha, double beta = 0.0) {
  constexpr int kSteps = 4000;
  struct State {
    double theta, dtheta, x, y;
  };
  auto rate = [&](const State& s) {
    return State{s.dtheta, -alpha * std::cos(s.theta - beta), std::cos(s.theta),
                 -std::sin(s.theta)};
  };
  auto shoot = [&](double slope) {
    State s{0.0, slope, 0.0, 0.0};
    const double h = 1.0 / kSteps;
    for (int i = 0; i < kSteps; ++i) {
      const State k1 = rate(s);
      const State k2 = rate({s.theta + 0.5 * h * k1.theta, s.dtheta + 0.5 * h * k1.dtheta,
                             s.x + 0.5 * h * k1.x, s.y + 0.5 * h * k1.y});
      const State k3 = rate({s.theta + 0.5 * h * k2.theta, s.dtheta + 0.5 * h * k2.dtheta,
                             s.x + 0.5 * h * k2.x, s.y + 0.5 * h * k2.y});
      const State k4 =
          rate({s.theta + h * k3.theta, s.dtheta + h * k3.dtheta, s.x + h * k3.x, s.y + h * k3.y});
      s.theta += h / 6.0 * (k1.theta + 2.0 * k2.theta + 2.0 * k3.theta + k4.theta);
      s.dtheta += h / 6.0 * (k1.dtheta + 2.0 * k2.dtheta + 2.0 * k3.dtheta + k4.dtheta);
      s.x += h / 6.0 * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x);
      s.y += h / 6.0 * (k1.y + 2.0 * k2.y + 2.0 * k3.y + k4.y);
    }
    return s;
  };
  double low = 0.0;
  double high = alpha;
  for (int i = 0; i < 80; ++i) {
    const double mid = 0.5 * (low + high);
    (shoot(mid).dtheta > 0.0 ? high : low) = mid;
  }
  const State tip = shoot(0.5 * (low + high));
  return {1.0 - tip.x, -tip.y, tip.theta};
}

/// The cantilever elastica under a follower tip force that stays normal to the tip (it points
/// down in the undeformed state and turns with the tip): Elastica(alpha, beta) with beta equal
/// to the tip angle it produces, found by the secant method on theta(1; beta) - beta.
inline ElasticaTip FollowerElastica(double alpha) {
  double b0 = 0.0;
  double g0 = Elastica(alpha, b0).angle - b0;
  double b1 = Elastica(alpha, 0.0).angle;
  for (int i = 0; i < 60; ++i) {
    const double g1 = Elastica(alpha, b1).angle - b1;
    if (g1 == g0 || std::abs(g1) < 1e-15) break;
    const double b2 = b1 - g1 * (b1 - b0) / (g1 - g0);
    b0 = b1;
    g0 = g1;
    b1 = b2;
  }
  return Elastica(alpha, b1);
}

}  // namespace cosmems::test
