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
// stretch: tau = tau0 + kappa int w'^2, kappa = EA g^2 / (2 EI).
//
// Multiple shooting: the span is cut into 16 segments, each integrated by RK4 (250 steps) from
// its own starting state, and Newton (finite-difference Jacobian, from the secant of the last two
// travels) solves for those states, beta and tau so that the states join, the far end's conditions
// hold and the control point (the tip, or midspan) sits at -s. One shot across the span grows
// the tension's modes exp(+-sqrt(tau) x) by exp(sqrt(tau)), past what doubles hold once
// tau ~ 1000 (a bridge with gap / thickness 10); a segment grows them by its 16th root. Travels
// are reached in steps of 0.01 of the gap from the last one solved. The fold is the largest beta
// over s: walk in steps of 0.05 until beta falls, then golden-section search.
class BeamShooting {
 public:
  BeamShooting(bool bridge, int exponent, double tau0 = 0.0, double kappa = 0.0)
      : bridge_(bridge), exponent_(exponent), tau0_(tau0), kappa_(kappa) {
    Start(0.0);
  }

  // beta at travel s.
  double Beta(double s) {
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(s - s_) / 0.01)));
    const double from = s_;
    for (int i = 1; i <= steps; ++i) Solve(from + (s - from) * i / steps);
    return u_[kUnknowns - 2];
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
  static constexpr int kSegments = 16, kStepsPerSegment = 250;
  // w''(0), w'''(0); the four states (w, w', w'', w''') at the start of segments 1..15; beta, tau.
  static constexpr int kUnknowns = 2 + 4 * (kSegments - 1) + 2;
  using Vector = Eigen::Matrix<double, kUnknowns, 1>;
  using State = std::array<double, 5>;  // w, w', w'', w''', int w'^2 over the segment

  // One segment of length 1/kSegments by RK4 from y (its integral restarted at 0).
  State Integrate(State y, double beta, double tau) const {
    auto f = [&](const State& v) {
      double power = 1.0;
      for (int i = 0; i < exponent_; ++i) power *= 1.0 + v[0];
      return State{v[1], v[2], v[3], tau * v[2] - beta / power, v[1] * v[1]};
    };
    const double h = 1.0 / (kSegments * kStepsPerSegment);
    y[4] = 0.0;
    for (int i = 0; i < kStepsPerSegment; ++i) {
      const State k1 = f(y);
      State t;
      for (int j = 0; j < 5; ++j) t[j] = y[j] + 0.5 * h * k1[j];
      const State k2 = f(t);
      for (int j = 0; j < 5; ++j) t[j] = y[j] + 0.5 * h * k2[j];
      const State k3 = f(t);
      for (int j = 0; j < 5; ++j) t[j] = y[j] + h * k3[j];
      const State k4 = f(t);
      for (int j = 0; j < 5; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    return y;
  }

  State Initial(const Vector& u, int segment) const {
    if (segment == 0) return {0.0, 0.0, u[0], u[1], 0.0};
    const int at = 2 + 4 * (segment - 1);
    return {u[at], u[at + 1], u[at + 2], u[at + 3], 0.0};
  }

  using Ends = std::array<State, kSegments>;

  Ends Shoot(const Vector& u) const {
    Ends ends;
    for (int k = 0; k < kSegments; ++k) {
      ends[k] = Integrate(Initial(u, k), u[kUnknowns - 2], u[kUnknowns - 1]);
    }
    return ends;
  }

  // The joins (4 per inner junction), the far end's two conditions, the control point and the
  // tension's equation, from the segments' ends.
  Vector Residual(const Vector& u, const Ends& ends, double s) const {
    const double tau = u[kUnknowns - 1];
    Vector r;
    double stretch = 0.0;
    int row = 0;
    for (int k = 0; k < kSegments; ++k) {
      stretch += ends[k][4];
      if (k + 1 < kSegments) {
        const State next = Initial(u, k + 1);
        for (int j = 0; j < 4; ++j) r[row++] = ends[k][j] - next[j];
      }
    }
    const State& end = ends.back();
    if (bridge_) {
      r[row++] = end[0];
      r[row++] = end[1];
      r[row++] = Initial(u, kSegments / 2)[0] + s;  // midspan starts a segment
      r[row++] = tau - tau0_ - kappa_ * stretch;
    } else {
      r[row++] = end[2];
      r[row++] = end[3];
      r[row++] = end[0] + s;
      r[row++] = tau - tau0_;
    }
    return r;
  }
  Vector Residual(const Vector& u, double s) const { return Residual(u, Shoot(u), s); }

  // The linear beam's solution at travel s, sampled at the segments' starts: a start for Newton.
  void Start(double s) {
    u_.setZero();
    previous_ = u_;
    previous_s_ = s;
    const double w2 = bridge_ ? -32.0 * s : -4.0 * s, w3 = bridge_ ? 192.0 * s : 8.0 * s;
    const double beta = bridge_ ? 384.0 * s : 8.0 * s;
    u_[0] = w2;
    u_[1] = w3;
    State y{0.0, 0.0, w2, w3, 0.0};
    for (int k = 1; k < kSegments; ++k) {
      y = Integrate(y, beta, tau0_);
      for (int j = 0; j < 4; ++j) u_[2 + 4 * (k - 1) + j] = y[j];
    }
    u_[kUnknowns - 2] = beta;
    u_[kUnknowns - 1] = tau0_;
    s_ = s;
  }

  // Newton at travel s from the last two solutions' secant (the linear solution to start).
  void Solve(double s) {
    if (s_ == 0.0) Start(s);
    Vector u = u_;
    if (previous_s_ != s_) u += (s - s_) / (s_ - previous_s_) * (u_ - previous_);
    for (int iteration = 0; iteration < 50; ++iteration) {
      const Ends ends = Shoot(u);
      const Vector r = Residual(u, ends, s);
      if (r.lpNorm<1>() < 1e-11 * (1.0 + std::abs(u[kUnknowns - 2]))) break;
      // A segment's starting state moves that segment's end alone; beta and tau move them all.
      Eigen::Matrix<double, kUnknowns, kUnknowns> jacobian;
      for (int j = 0; j < kUnknowns; ++j) {
        Vector v = u;
        const double h = 1e-7 * std::max(1.0, std::abs(u[j]));
        v[j] += h;
        const int segment = j < 2 ? 0 : j < kUnknowns - 2 ? 1 + (j - 2) / 4 : -1;
        Ends moved = ends;
        if (segment >= 0) {
          moved[segment] = Integrate(Initial(v, segment), v[kUnknowns - 2], v[kUnknowns - 1]);
        } else {
          moved = Shoot(v);
        }
        jacobian.col(j) = (Residual(v, moved, s) - r) / h;
      }
      const Vector step = jacobian.partialPivLu().solve(-r);
      // Whole steps: the residual mixes scales (the tension's equation grows quadratically), so
      // its norm is no merit function; a step is halved only to stay where the beam is finite.
      double alpha = 1.0;
      while (alpha > 1e-3 && !Residual(u + alpha * step, s).allFinite()) alpha *= 0.5;
      u += alpha * step;
    }
    previous_ = u_;
    previous_s_ = s_;
    u_ = u;
    s_ = s;
  }

  bool bridge_;
  int exponent_;
  double tau0_, kappa_;
  Vector u_, previous_;
  double s_ = 0.0, previous_s_ = 0.0;  ///< the travels u_ and previous_ solve
};

}  // namespace cosmems::test
