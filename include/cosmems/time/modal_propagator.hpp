#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/time/mode_step.hpp"

namespace cosmems {

/// Exact propagation of decoupled modal oscillators under loads that vary linearly over a step.
///
/// Loads are fixed spatial patterns P (n x m columns) times time functions s(t), f = P s. Per
/// mode, the step map (ModeStep) with g = phi^T P s is the exact solution for s linear in t over
/// the step; so the step is limited by how fast the load changes,
/// never by stability or by the modal frequencies. The truncated modes answer statically:
/// d = Phi q + R P s with R = K^-1 - sum_i phi_i phi_i^T / w_i^2 (`residual_flexibility` = R P),
/// so a point load still produces its local deflection. Step() allocates nothing.
class ModalPropagator {
 public:
  /// `shapes`: n x k unit-modal-mass mode shapes; `patterns`: n x m load patterns;
  /// `residual_flexibility`: n x m (R P), or an empty matrix for no static correction.
  ModalPropagator(std::vector<ModalCoordinate> modes, const Eigen::MatrixXd& shapes,
                  const Eigen::MatrixXd& patterns, const Eigen::MatrixXd& residual_flexibility,
                  double time_step)
      : modes_(std::move(modes)),
        shapes_(shapes),
        modal_loads_(shapes.transpose() * patterns),
        residual_(residual_flexibility),
        dt_(time_step) {
    RequirePositive("time_step", time_step);
    const int k = static_cast<int>(modes_.size());
    steps_.reserve(modes_.size());
    for (const ModalCoordinate& mode : modes_) {
      RequirePositive("mode omega", mode.omega);
      steps_.push_back(ModeStep::Make(mode, dt_));
    }
    q_.setZero(k);
    qdot_.setZero(k);
    s_.setZero(patterns.cols());
    g_.setZero(k);
    g_next_.setZero(k);
  }

  /// The modal state q, q' with the load amplitudes s0 at t = 0 (ModalModel::Project gives q
  /// from a physical state: of d - R P s0 for a displacement d, since d = Phi q + R P s).
  void Initialize(const Eigen::VectorXd& q0, const Eigen::VectorXd& qdot0,
                  const Eigen::VectorXd& s0) {
    RequireSize("q0", q0.size(), q_.size(), "one per mode");
    RequireSize("qdot0", qdot0.size(), q_.size(), "one per mode");
    RequireSize("s0", s0.size(), s_.size(), "one per load pattern");
    q_ = q0;
    qdot_ = qdot0;
    s_ = s0;
    g_ = modal_loads_ * s_;
    time_ = 0.0;
  }

  /// Advances one step to the load amplitudes s_next at t + dt.
  [[nodiscard]] Status Step(const Eigen::VectorXd& s_next) {
    // By hand: at a few modes Eigen's general products and their dispatch cost more than the
    // arithmetic, (14 + 2m) k flops (m patterns).
    const Eigen::Index k = q_.size(), m = s_next.size();
    double sum = 0.0;  // non-finite when any coordinate is: one test per step, not two per mode
    for (Eigen::Index i = 0; i < k; ++i) {
      double g = 0.0;  // phi_i^T P s_next
      for (Eigen::Index j = 0; j < m; ++j) g += modal_loads_(i, j) * s_next[j];
      const ModeStep& step = steps_[static_cast<std::size_t>(i)];
      const double q = q_[i], v = qdot_[i], g0 = g_[i];
      q_[i] = step.a(0, 0) * q + step.a(0, 1) * v + step.b0[0] * g0 + step.b1[0] * g;
      qdot_[i] = step.a(1, 0) * q + step.a(1, 1) * v + step.b0[1] * g0 + step.b1[1] * g;
      g_next_[i] = g;
      sum += q_[i] + qdot_[i];
    }
    if (!std::isfinite(sum)) return Status::kNonFinite;
    g_.swap(g_next_);
    s_ = s_next;
    time_ += dt_;
    return Status::kOk;
  }

  /// d = Phi q + R P s into `out` (n); allocates nothing when `out` has the right size.
  void Displacement(Eigen::VectorXd& out) const {
    out.noalias() = shapes_ * q_;
    if (residual_.size() > 0) out.noalias() += residual_ * s_;
  }

  /// One physical degree of freedom of the displacement, at O(k + m) cost.
  double DisplacementAt(Eigen::Index dof) const {
    double value = shapes_.row(dof).dot(q_);
    if (residual_.size() > 0) value += residual_.row(dof).dot(s_);
    return value;
  }

  const Eigen::VectorXd& modal_displacement() const { return q_; }
  const Eigen::VectorXd& modal_velocity() const { return qdot_; }
  double time() const { return time_; }
  double time_step() const { return dt_; }

 private:
  std::vector<ModalCoordinate> modes_;
  Eigen::MatrixXd shapes_;
  Eigen::MatrixXd modal_loads_;
  Eigen::MatrixXd residual_;
  double dt_;
  double time_ = 0.0;
  std::vector<ModeStep> steps_;
  Eigen::VectorXd q_, qdot_, s_, g_, g_next_;
};

}  // namespace cosmems
