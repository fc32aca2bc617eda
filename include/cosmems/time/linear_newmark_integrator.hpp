#pragma once

#include <cmath>

#include <Eigen/Core>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/rayleigh_damping.hpp"

namespace cosmems {

/// The linear fast path of the Newmark family: M a + C v + K d = f with C = cM M + cK K.
///
/// Every member of the generalised-alpha family solves, per step, the same matrix
///   S = ((1 - am) + (1 - af) gamma dt cM) M + ((1 - af) gamma dt cK + (1 - af) beta dt^2) K
/// for a_(n+1), so S is factorised once at construction and a step is one back-solve whose
/// right-hand side (band products with K, and with M unless the member needs none) is formed
/// inside its forward sweep, then one pass of updates. Step() allocates nothing and throws nothing.
class LinearNewmarkIntegrator {
 public:
  /// `mass` and `stiffness` share one band pattern (as a BeamModel's do) and must outlive the
  /// integrator. Throws std::invalid_argument for a non-positive or non-finite time step.
  LinearNewmarkIntegrator(const SymmetricBandMatrix& mass, const SymmetricBandMatrix& stiffness,
                          RayleighDamping damping, GeneralizedAlphaParameters parameters,
                          double time_step, SpdSolverKind solver = SpdSolverKind::kAuto)
      : mass_(mass), stiffness_(stiffness), damping_(damping), p_(parameters), dt_(time_step) {
    RequirePositive("time_step", time_step);
    const int n = mass.size();
    d_.setZero(n);
    v_.setZero(n);
    a_.setZero(n);
    a_new_.setZero(n);
    f_.setZero(n);
    rhs_.setZero(n);
    x_m_.setZero(n);
    x_k_.setZero(n);
    const double one_af = 1.0 - p_.alpha_f;
    const double s_m = (1.0 - p_.alpha_m) + one_af * p_.gamma * dt_ * damping_.mass;
    const double s_k = one_af * (p_.gamma * dt_ * damping_.stiffness + p_.beta * dt_ * dt_);
    SymmetricBandMatrix s(n, mass.bandwidth());
    s.mutable_data() = s_m * mass.data() + s_k * stiffness.data();
    status_ = solver_.Compute(s, solver);
    uses_mass_ = p_.alpha_m != 0.0 || damping_.mass != 0.0;
  }

  /// Sets the state at t = 0 from d0, v0 and the load f0 there; the initial acceleration
  /// solves M a0 = f0 - C v0 - K d0 (one extra factorisation of M, here and only here).
  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& f0) {
    if (status_ != Status::kOk) return status_;
    stiffness_.Multiply(d0 + damping_.stiffness * v0, rhs_);
    Eigen::VectorXd a0 = f0 - rhs_;
    mass_.Multiply(v0, rhs_);
    a0 -= damping_.mass * rhs_;
    SpdSolver mass_solver;
    if (mass_solver.Compute(mass_) != Status::kOk) return status_ = mass_solver.info();
    mass_solver.SolveInPlace(a0);
    if (!a0.allFinite()) return status_ = Status::kNonFinite;
    SetState(d0, v0, a0, f0);
    time_ = 0.0;
    return status_;
  }

  /// Restarts from a full state (d, v, a) and the load f at the current time, e.g. a
  /// checkpoint; unlike Initialize() it takes a as given.
  void SetState(const Eigen::VectorXd& d, const Eigen::VectorXd& v, const Eigen::VectorXd& a,
                const Eigen::VectorXd& f) {
    d_ = d;
    v_ = v;
    a_ = a;
    f_ = f;
    for (Eigen::Index i = 0; i < d_.size(); ++i) PrepareRow(i);
  }

  /// Advances by one time step to the load f_next at t + dt. A non-finite result is reported
  /// as Status::kNonFinite and the step is not taken.
  [[nodiscard]] Status Step(const Eigen::VectorXd& f_next) {
    if (status_ != Status::kOk) return status_;
    const double af = p_.alpha_f;
    rhs_ = (1.0 - af) * f_next + af * f_;
    // a_(n+1) = S^-1 (f_(n+1-af) - M x_m - K x_k); x_m, x_k were prepared by the last update.
    solver_.SolveResidual(rhs_, uses_mass_ ? &mass_ : nullptr, x_m_, stiffness_, x_k_, a_new_);
    if (!a_new_.allFinite()) return Status::kNonFinite;
    // One pass: Newmark's updates, and this row's x_m, x_k for the next step.
    const double dd_a = dt_ * dt_ * (0.5 - p_.beta), dd_new = dt_ * dt_ * p_.beta;
    const double dv_a = dt_ * (1.0 - p_.gamma), dv_new = dt_ * p_.gamma;
    for (Eigen::Index i = 0; i < d_.size(); ++i) {
      d_[i] += dt_ * v_[i] + dd_a * a_[i] + dd_new * a_new_[i];
      v_[i] += dv_a * a_[i] + dv_new * a_new_[i];
      a_[i] = a_new_[i];
      f_[i] = f_next[i];
      PrepareRow(i);
    }
    time_ += dt_;
    return Status::kOk;
  }

  const Eigen::VectorXd& displacement() const { return d_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  const Eigen::VectorXd& acceleration() const { return a_; }
  double time() const { return time_; }
  double time_step() const { return dt_; }
  Status info() const { return status_; }
  SpdSolverKind solver_kind() const { return solver_.kind(); }

 private:
  // The vectors the next step multiplies by M and K, at row i: with
  // vp = v + (1-af)(1-gamma) dt a and dp = d + (1-af)(dt v + dt^2 (1/2-beta) a),
  // x_m = am a + cM vp and x_k = cK vp + dp.
  void PrepareRow(Eigen::Index i) {
    const double one_af = 1.0 - p_.alpha_f;
    const double vp = v_[i] + one_af * (1.0 - p_.gamma) * dt_ * a_[i];
    x_m_[i] = p_.alpha_m * a_[i] + damping_.mass * vp;
    x_k_[i] = damping_.stiffness * vp + d_[i] + one_af * (dt_ * v_[i] + dt_ * dt_ * (0.5 - p_.beta) * a_[i]);
  }

  const SymmetricBandMatrix& mass_;
  const SymmetricBandMatrix& stiffness_;
  RayleighDamping damping_;
  GeneralizedAlphaParameters p_;
  double dt_;
  double time_ = 0.0;
  SpdSolver solver_;
  Status status_ = Status::kOk;
  bool uses_mass_ = true;  ///< x_m = am a + cM vp is not identically zero
  Eigen::VectorXd d_, v_, a_, a_new_, f_, rhs_, x_m_, x_k_;
};

}  // namespace cosmems
