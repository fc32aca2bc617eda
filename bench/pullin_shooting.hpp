#pragma once

// An independent oracle for electrostatic pull-in: the beam equation under the parallel-plate
// pressure, solved by shooting, its fold found by a golden-section search.

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>

namespace cosmems::bench {

/// A beam over an electrode under its whole length, in units of its length L and the gap g:
///   w'''' - tau w'' = -beta / (1 + w)^2,   beta = eps0 b V^2 L^4 / (2 EI g^3),
/// clamped at x = 0 (w = w' = 0). A cantilever is free at x = 1 (w'' = w''' = 0, tau = 0); a
/// bridge is clamped there (w = w' = 0) and, held axially, stretches: tau = kappa int w'^2 dx,
/// kappa = EA g^2 / (2 EI) (0 for a bridge without stretching).
///
/// At a travel s (the control point, the tip or midspan, held at w = -s) the unknowns
/// u = (w''(0), w'''(0), beta, tau) solve four end conditions; Newton with a forward-difference
/// Jacobian, each residual an RK4 integration over 4000 steps (error ~1e-14) with int w'^2 as a
/// fifth state. Pull-in is the fold: the largest beta over s, bracketed by walking s in steps of
/// 0.02 until beta falls and located by golden-section search to 1e-9 in s (beta is flat there,
/// so its error is far below that).
class PullInShooting {
 public:
  struct Fold {
    double travel = 0.0;  ///< s at pull-in (fraction of the gap)
    double beta = 0.0;
  };

  PullInShooting(bool bridge, double kappa) : bridge_(bridge), kappa_(kappa) {}

  /// beta at travel s, by Newton from the last solution (from the small-deflection one first).
  double Beta(double s) {
    if (!started_) {
      // Under a uniform load beta: tip -beta / 8 (cantilever), midspan -beta / 384 (bridge).
      unknowns_ = bridge_ ? Eigen::Vector4d(-32.0 * s, 192.0 * s, 384.0 * s, 0.0)
                          : Eigen::Vector4d(-4.0 * s, 8.0 * s, 8.0 * s, 0.0);
      started_ = true;
    }
    for (int iteration = 0; iteration < 50; ++iteration) {
      const Eigen::Vector4d r = Residual(unknowns_, s);
      if (r.lpNorm<1>() < 1e-13 * std::max(1.0, std::abs(unknowns_[2]))) break;
      Eigen::Matrix4d jacobian;
      for (int j = 0; j < 4; ++j) {
        Eigen::Vector4d shifted = unknowns_;
        const double h = 1e-7 * std::max(1.0, std::abs(unknowns_[j]));
        shifted[j] += h;
        jacobian.col(j) = (Residual(shifted, s) - r) / h;
      }
      unknowns_ -= jacobian.fullPivLu().solve(r);
    }
    return unknowns_[2];
  }

  Fold PullIn() {
    double s = 0.02;
    double last = Beta(s);
    while (true) {
      const double next = Beta(s + 0.02);
      if (next <= last) break;
      last = next;
      s += 0.02;
    }
    // The fold lies in [s - 0.02, s + 0.02].
    const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = std::max(0.0, s - 0.02);
    double b = s + 0.02;
    double c = b - ratio * (b - a);
    double d = a + ratio * (b - a);
    double fc = Beta(c);
    double fd = Beta(d);
    while (b - a > 1e-9) {
      if (fc > fd) {
        b = d;
        d = c;
        fd = fc;
        c = b - ratio * (b - a);
        fc = Beta(c);
      } else {
        a = c;
        c = d;
        fc = fd;
        d = a + ratio * (b - a);
        fd = Beta(d);
      }
    }
    const double travel = 0.5 * (a + b);
    return {travel, Beta(travel)};
  }

 private:
  using State = std::array<double, 5>;  // w, w', w'', w''', int w'^2

  Eigen::Vector4d Residual(const Eigen::Vector4d& u, double s) const {
    const double beta = u[2];
    const double tau = u[3];
    auto rate = [&](const State& y) {
      return State{y[1], y[2], y[3], tau * y[2] - beta / ((1.0 + y[0]) * (1.0 + y[0])),
                   y[1] * y[1]};
    };
    constexpr int kSteps = 4000;
    const double h = 1.0 / kSteps;
    State y = {0.0, 0.0, u[0], u[1], 0.0};
    double midspan = 0.0;
    for (int i = 0; i < kSteps; ++i) {
      if (i == kSteps / 2) midspan = y[0];
      const State k1 = rate(y);
      const State k2 = rate(Shift(y, k1, 0.5 * h));
      const State k3 = rate(Shift(y, k2, 0.5 * h));
      const State k4 = rate(Shift(y, k3, h));
      for (int j = 0; j < 5; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    if (bridge_) return {y[0], y[1], midspan + s, tau - kappa_ * y[4]};
    return {y[2], y[3], y[0] + s, tau};
  }

  static State Shift(const State& y, const State& k, double h) {
    State out;
    for (int j = 0; j < 5; ++j) out[j] = y[j] + h * k[j];
    return out;
  }

  bool bridge_;
  double kappa_;
  Eigen::Vector4d unknowns_ = Eigen::Vector4d::Zero();
  bool started_ = false;
};

}  // namespace cosmems::bench
