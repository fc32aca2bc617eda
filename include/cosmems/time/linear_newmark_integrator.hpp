#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_rows.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/initial_acceleration.hpp"
#include "cosmems/time/newton_stats.hpp"
#include "cosmems/time/rayleigh_damping.hpp"

namespace cosmems {

/// The linear fast path of the Newmark family: M a + C v + K d = f with C = cM M + cK K.
///
/// Every member of the generalised-alpha family solves, per step, the same matrix
///   S = ((1 - am) + (1 - af) gamma dt cM) M + ((1 - af) gamma dt cK + (1 - af) beta dt^2) K
/// for a_(n+1), so S is factorised once at construction and a step is a row product with K
/// (and with M, unless the member needs none; BandRows), one back-solve and one pass of
/// updates.
/// Step() allocates nothing and throws nothing.
class LinearNewmarkIntegrator {
 public:
  /// `mass` and `stiffness` share one band pattern (as a BeamModel's do) and must outlive the
  /// integrator. Throws std::invalid_argument for a non-positive or non-finite time step.
  LinearNewmarkIntegrator(const SymmetricBandMatrix& mass, const SymmetricBandMatrix& stiffness,
                          RayleighDamping damping, GeneralizedAlphaParameters parameters,
                          double time_step, SpdSolverKind solver = SpdSolverKind::kAuto)
      : mass_(mass),
        stiffness_(stiffness),
        damping_(damping),
        p_(parameters),
        dt_(time_step),
        coefficients_(MakeCoefficients(parameters, damping, time_step)),
        stiffness_rows_(stiffness),
        pad_(stiffness.bandwidth()) {
    RequirePositive("time_step", time_step);
    const int n = mass.size();
    d_.setZero(n);
    v_.setZero(n);
    a_.setZero(n);
    a_new_.setZero(n);
    f_.setZero(n);
    // x_m, x_k carry the zero padding of the row products (BandRows).
    x_m_.setZero(n + 2 * pad_);
    x_k_.setZero(n + 2 * pad_);

    const double one_af = 1.0 - p_.alpha_f;
    const double s_m = (1.0 - p_.alpha_m) + one_af * p_.gamma * dt_ * damping_.mass;
    const double s_k = one_af * (p_.gamma * dt_ * damping_.stiffness + p_.beta * dt_ * dt_);
    SymmetricBandMatrix s(n, mass.bandwidth());
    s.mutable_data() = s_m * mass.data() + s_k * stiffness.data();
    status_ = solver_.Compute(s, solver);
    uses_mass_ = p_.alpha_m != 0.0 || damping_.mass != 0.0;
    if (uses_mass_) mass_rows_ = BandRows(mass);
  }

  /// Sets the state at t = 0 from d0, v0 and the load f0 there; the initial acceleration
  /// solves M a0 = f0 - C v0 - K d0 (one extra factorisation of M, here and only here).
  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& f0) {
    if (status_ != Status::kOk) return status_;
    Eigen::VectorXd a0;
    status_ = InitialAcceleration(mass_, stiffness_, damping_, d0, v0, f0, a0);
    if (status_ != Status::kOk) return status_;
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
    const Coefficients& c = coefficients_;
    for (Eigen::Index i = 0; i < d_.size(); ++i) {
      x_k_[pad_ + i] = c.Xk(d_[i], v_[i], a_[i]);
      x_m_[pad_ + i] = c.Xm(v_[i], a_[i]);
    }
  }

  /// Advances by one time step to the load f_next at t + dt. A non-finite result is reported
  /// as Status::kNonFinite and the step is not taken.
  [[nodiscard]] Status Step(const Eigen::VectorXd& f_next) {
    if (status_ != Status::kOk) return status_;
    const double af = p_.alpha_f;
    // a_(n+1) = S^-1 (f_(n+1-af) - M x_m - K x_k); x_m, x_k were prepared by the last update.
    if (af == 0.0) {
      a_new_ = f_next;
    } else {
      a_new_ = (1.0 - af) * f_next + af * f_;
    }
    if (uses_mass_) mass_rows_.SubtractProduct(x_m_.data(), a_new_.data());
    stiffness_rows_.SubtractProduct(x_k_.data(), a_new_.data());
    solver_.SolveInPlace(a_new_);
    if (!a_new_.allFinite()) return Status::kNonFinite;
    // One pass: Newmark's updates and the next step's x_k. Coefficients live in locals and the
    // vectors behind restrict pointers: otherwise every store could alias a member, forcing
    // reloads and ruling out vectorisation. The pass is memory-bound, so it touches only what
    // this member needs: f_n only when af != 0, x_m only when M enters.
    const Coefficients c = coefficients_;
    double* __restrict d = d_.data();
    double* __restrict v = v_.data();
    const double* __restrict a = a_.data();
    double* __restrict xk = x_k_.data() + pad_;
    const double* __restrict an = a_new_.data();
    const Eigen::Index n = d_.size();
    for (Eigen::Index i = 0; i < n; ++i) {
      d[i] += c.dt * v[i] + c.dd_a * a[i] + c.dd_new * an[i];
      v[i] += c.dv_a * a[i] + c.dv_new * an[i];
      xk[i] = c.Xk(d[i], v[i], an[i]);
    }
    if (uses_mass_) {
      double* __restrict xm = x_m_.data() + pad_;
      for (Eigen::Index i = 0; i < n; ++i) xm[i] = c.Xm(v[i], an[i]);
    }
    if (p_.alpha_f != 0.0) f_ = f_next;
    a_.swap(a_new_);
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
  /// The linear path solves once a step with the factor made at set-up: no Newton, all zero.
  const NewtonStats& last_stats() const { return no_newton_; }

 private:
  // The step's constant coefficients. The vectors the next step multiplies by M and K are, with
  // vp = v + (1-af)(1-gamma) dt a and dp = d + (1-af)(dt v + dt^2 (1/2-beta) a),
  // x_m = am a + cM vp and x_k = cK vp + dp.
  // Each product's coefficients are folded ahead (x_k = d + k_v v + k_a a): 4 operations an
  // unknown instead of 8.
  struct Coefficients {
    double dt, dd_a, dd_new, dv_a, dv_new, k_v, k_a, m_v, m_a;

    double Xk(double d, double v, double a) const { return d + k_v * v + k_a * a; }
    double Xm(double v, double a) const { return m_v * v + m_a * a; }
  };

  static Coefficients MakeCoefficients(const GeneralizedAlphaParameters& p, RayleighDamping c,
                                       double dt) {
    const double one_af = 1.0 - p.alpha_f;
    const double vp_a = one_af * (1.0 - p.gamma) * dt;  // vp = v + vp_a a
    const double dp_v = one_af * dt, dp_a = one_af * dt * dt * (0.5 - p.beta);
    return {dt,
            dt * dt * (0.5 - p.beta),
            dt * dt * p.beta,
            dt * (1.0 - p.gamma),
            dt * p.gamma,
            c.stiffness + dp_v,
            c.stiffness * vp_a + dp_a,
            c.mass,
            p.alpha_m + c.mass * vp_a};
  }

  const SymmetricBandMatrix& mass_;
  const SymmetricBandMatrix& stiffness_;
  RayleighDamping damping_;
  GeneralizedAlphaParameters p_;
  double dt_;
  double time_ = 0.0;
  SpdSolver solver_;
  Status status_ = Status::kOk;
  Coefficients coefficients_;
  BandRows stiffness_rows_;
  BandRows mass_rows_;
  int pad_;
  bool uses_mass_ = true;  ///< x_m = am a + cM vp is not identically zero
  Eigen::VectorXd d_, v_, a_, a_new_, f_, x_m_, x_k_;
  NewtonStats no_newton_;
};

}  // namespace cosmems
