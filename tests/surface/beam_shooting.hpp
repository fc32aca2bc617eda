#pragma once

// An oracle for pull-in under a pressure that grows as the gap closes, independent of the finite
// elements: the beam equation solved by shooting. Shared by the pull-in tests and the
// accuracy-versus-time report.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace cosmems::test {

// A beam pulled by a pressure P / d^n, in units of L and g: w'''' - tau w'' = -beta / (1 + w)^n
// with beta = b P L^4 / (EI g^(n+1)) and tau = N L^2 / EI. Clamped at x = 0 (w = w' = 0); a
// cantilever is free at x = 1 (w'' = w''' = 0), a bridge clamped there too (w = w' = 0) and may
// stretch: tau = tau0 + kappa int w'^2, kappa = EA g^2 / (2 EI). Shooting on (w''(0), w'''(0),
// beta, tau) for a given deflection -s at the control point (the tip, or midspan), by Newton
// with a finite-difference Jacobian and RK4 on 2000 steps (error ~1e-13); the fold is the
// largest beta over s: walk in steps of 0.05 until beta falls, then golden-section search.
class BeamShooting {
 public:
  BeamShooting(bool bridge, int exponent, double tau0 = 0.0, double kappa = 0.0)
      : bridge_(bridge), exponent_(exponent), tau0_(tau0), kappa_(kappa) {}

  std::array<double, 4> Residual(const std::array<double, 4>& u, double s) const {
    std::array<double, 5> y = {0.0, 0.0, u[0], u[1], 0.0};  // w, w', w'', w''', int w'^2
    const double beta = u[2], tau = u[3];
    auto f = [&](const std::array<double, 5>& v) {
      return std::array<double, 5>{
          v[1], v[2], v[3], tau * v[2] - beta / std::pow(1.0 + v[0], exponent_), v[1] * v[1]};
    };
    const int steps = 2000;
    const double h = 1.0 / steps;
    double midspan = 0.0;
    for (int i = 0; i < steps; ++i) {
      if (i == steps / 2) midspan = y[0];
      const auto k1 = f(y);
      std::array<double, 5> t;
      for (int j = 0; j < 5; ++j) t[j] = y[j] + 0.5 * h * k1[j];
      const auto k2 = f(t);
      for (int j = 0; j < 5; ++j) t[j] = y[j] + 0.5 * h * k2[j];
      const auto k3 = f(t);
      for (int j = 0; j < 5; ++j) t[j] = y[j] + h * k3[j];
      const auto k4 = f(t);
      for (int j = 0; j < 5; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    if (bridge_) return {y[0], y[1], midspan + s, tau - tau0_ - kappa_ * y[4]};
    return {y[2], y[3], y[0] + s, tau - tau0_};
  }

  // beta at travel s, Newton from the last solution (the linear one to start).
  double Beta(double s) {
    std::array<double, 4> u = u_;
    if (!started_) {
      u = bridge_ ? std::array<double, 4>{-32.0 * s, 192.0 * s, 384.0 * s, tau0_}
                  : std::array<double, 4>{-4.0 * s, 8.0 * s, 8.0 * s, tau0_};
    }
    for (int iteration = 0; iteration < 50; ++iteration) {
      const std::array<double, 4> r = Residual(u, s);
      if (std::abs(r[0]) + std::abs(r[1]) + std::abs(r[2]) + std::abs(r[3]) < 1e-12) break;
      Eigen::Matrix4d jacobian;
      for (int j = 0; j < 4; ++j) {
        std::array<double, 4> v = u;
        const double h = 1e-7 * std::max(1.0, std::abs(u[j]));
        v[j] += h;
        const std::array<double, 4> rv = Residual(v, s);
        for (int i = 0; i < 4; ++i) jacobian(i, j) = (rv[i] - r[i]) / h;
      }
      const Eigen::Vector4d step = jacobian.lu().solve(-Eigen::Vector4d(r[0], r[1], r[2], r[3]));
      for (int j = 0; j < 4; ++j) u[j] += step[j];
    }
    u_ = u;
    started_ = true;
    return u[2];
  }

  // (travel, beta) at the fold.
  std::pair<double, double> Fold() {
    double s = 0.05, last = Beta(s);
    for (double next; (next = Beta(s + 0.05)) > last; s += 0.05) last = next;
    double a = std::max(0.0, s - 0.05), b = s + 0.05;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = Beta(c), fd = Beta(d);
    while (b - a > 1e-7) {
      if (fc > fd) {
        b = d, d = c, fd = fc, c = b - g * (b - a), fc = Beta(c);
      } else {
        a = c, c = d, fc = fd, d = a + g * (b - a), fd = Beta(d);
      }
    }
    return {0.5 * (a + b), Beta(0.5 * (a + b))};
  }

 private:
  bool bridge_;
  int exponent_;
  double tau0_, kappa_;
  std::array<double, 4> u_{};
  bool started_ = false;
};

}  // namespace cosmems::test
