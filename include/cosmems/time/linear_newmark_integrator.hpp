#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/band_kernels.hpp"
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
/// Step() allocates nothing and throws nothing; it writes the new state beside the old one, so
/// Undo() returns to the step's start exactly (a caller that steps ahead to test the result).
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
    for (Eigen::VectorXd* x : {&d_, &v_, &a_, &d_new_, &v_new_, &a_new_, &f_, &f_old_}) {
      x->setZero(n);
    }
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
    PrepareProducts();
  }

  /// Advances by one time step to the load f_next at t + dt. A non-finite result is reported
  /// as Status::kNonFinite and the step is not taken.
  [[nodiscard]] Status Step(const Eigen::VectorXd& f_next) {
    if (status_ != Status::kOk) return status_;
    // a_(n+1) = S^-1 (f_(n+1-af) - M x_m - K x_k); x_m, x_k were prepared by the last update.
    // The band factor takes the products and the updates into its sweeps; the others solve,
    // then update in a pass of their own.
    bool finite = true;
    const BandCholesky* band = solver_.band();
    const bool fused =
        band != nullptr && internal::DispatchBandwidth(band->bandwidth(), [&](auto w) {
          finite = SolveAndUpdate<decltype(w)::value>(f_next, *band);
        });
    if (!fused) {
      const double af = p_.alpha_f;
      if (af == 0.0) {
        a_new_ = f_next;
      } else {
        a_new_ = (1.0 - af) * f_next + af * f_;
      }
      if (uses_mass_) mass_rows_.SubtractProduct(x_m_.data(), a_new_.data());
      stiffness_rows_.SubtractProduct(x_k_.data(), a_new_.data());
      solver_.SolveInPlace(a_new_);
      finite = a_new_.allFinite();
      if (finite) {
        Update(coefficients_, d_.size(), d_.data(), v_.data(), a_.data(), a_new_.data(),
               d_new_.data(), v_new_.data(), x_k_.data() + pad_,
               uses_mass_ ? x_m_.data() + pad_ : nullptr);
      }
    }
    if (!finite) {  // the state is untouched; the products' vectors may not be
      PrepareProducts();
      return Status::kNonFinite;
    }
    if (p_.alpha_f != 0.0) {
      f_old_.swap(f_);
      f_ = f_next;
    }
    Swap();  // the old state stays beside the new one, for Undo()
    time_ += dt_;
    return Status::kOk;
  }

  /// Back to the start of the last step taken: the state bit for bit. Once only: the step
  /// before it is gone.
  void Undo() {
    Swap();
    if (p_.alpha_f != 0.0) f_.swap(f_old_);
    time_ -= dt_;
    PrepareProducts();
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

    // Newmark's updates of d and v by the old and new accelerations (the increment summed first).
    double D(double d, double v, double a, double an) const {
      return d + (dt * v + dd_a * a + dd_new * an);
    }
    double V(double v, double a, double an) const { return v + (dv_a * a + dv_new * an); }
    double Xk(double d, double v, double a) const { return d + k_v * v + k_a * a; }
    double Xm(double v, double a) const { return m_v * v + m_a * a; }
  };

  // The step on the band factor (BandCholesky::SolveRows): each row's products, f_i - M_i x_m -
  // K_i x_k, made as the forward sweep reaches it, and Newmark's updates of unknown j (with the
  // next step's x_k and x_m) done as the backward sweep solves a_(n+1),j. The sweeps wait on one
  // multiply-add per row and this work fills the waits: one pass over the unknowns, not four.
  // Returns whether every a_(n+1),j is finite; the state (d_, v_, a_) is written beside, not
  // over.
  template <int W>
  bool SolveAndUpdate(const Eigen::VectorXd& f_next, const BandCholesky& band) {
    const double af = p_.alpha_f, one_af = 1.0 - af;
    const double* f_n1 = f_next.data();
    const double* f_n = f_.data();
    const double* x_m = x_m_.data();  // padded, as the rows take them
    const double* x_k = x_k_.data();
    const bool mass = uses_mass_;
    auto rhs = [&](int i) {
      double b = af == 0.0 ? f_n1[i] : one_af * f_n1[i] + af * f_n[i];
      if (mass) b -= mass_rows_.RowProduct<W>(i, x_m);
      return b - stiffness_rows_.RowProduct<W>(i, x_k);
    };
    const Coefficients c = coefficients_;
    const double* d = d_.data();
    const double* v = v_.data();
    const double* a = a_.data();
    double* dn = d_new_.data();
    double* vn = v_new_.data();
    double* xk = x_k_.data() + pad_;  // the forward sweep is done with the old values
    double* xm = x_m_.data() + pad_;
    bool finite = true;
    auto solved = [&](int j, double an) {
      finite &= std::isfinite(an);
      dn[j] = c.D(d[j], v[j], a[j], an);
      vn[j] = c.V(v[j], a[j], an);
      xk[j] = c.Xk(dn[j], vn[j], an);
      if (mass) xm[j] = c.Xm(vn[j], an);
    };
    band.SolveRows<W>(a_new_.data(), rhs, solved);
    return finite;
  }

  // The pass is memory-bound, so it touches only what this member needs (x_m only when M
  // enters). The vectors come in as restrict parameters, which the compiler honours (on local
  // pointers it may not): otherwise each store could alias the next load, and the loop, with
  // seven vectors, would stay scalar.
  static void Update(const Coefficients c, Eigen::Index n, const double* __restrict d,
                     const double* __restrict v, const double* __restrict a,
                     const double* __restrict an, double* __restrict dn, double* __restrict vn,
                     double* __restrict xk, double* __restrict xm) {
    for (Eigen::Index i = 0; i < n; ++i) {
      dn[i] = c.D(d[i], v[i], a[i], an[i]);
      vn[i] = c.V(v[i], a[i], an[i]);
      xk[i] = c.Xk(dn[i], vn[i], an[i]);
    }
    if (xm == nullptr) return;
    for (Eigen::Index i = 0; i < n; ++i) xm[i] = c.Xm(vn[i], an[i]);
  }

  void Swap() {  // buffers, not values: allocates nothing
    d_.swap(d_new_);
    v_.swap(v_new_);
    a_.swap(a_new_);
  }

  // x_k and x_m from the state (d, v, a), as the last step's update would have left them.
  void PrepareProducts() {
    const Coefficients& c = coefficients_;
    for (Eigen::Index i = 0; i < d_.size(); ++i) {
      x_k_[pad_ + i] = c.Xk(d_[i], v_[i], a_[i]);
      x_m_[pad_ + i] = c.Xm(v_[i], a_[i]);
    }
  }

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
  Eigen::VectorXd d_, v_, a_, d_new_, v_new_, a_new_, f_, f_old_, x_m_, x_k_;
  NewtonStats no_newton_;
};

}  // namespace cosmems
