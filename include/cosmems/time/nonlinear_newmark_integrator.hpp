#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/initial_acceleration.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/rayleigh_damping.hpp"

namespace cosmems {

/// The nonlinear path of the Newmark family: M a + C v + K d + r(d) = f, generalised-alpha
/// balance, Newton on d_(n+1) with the consistent tangent
///   J = (1-am)/(beta dt^2) M + (1-af) gamma/(beta dt) C + (1-af) (K + dr/dd (d_(n+1-af))).
/// A step whose Newton iterations fail (no convergence, non-finite values, a force outside its
/// domain) is retried as two half steps, recursively up to NewtonOptions::max_cuts; if even
/// that fails, the state is left at the start of the step and the status says why. Steps
/// allocate nothing. Implicit members only (beta > 0).
class NonlinearNewmarkIntegrator {
 public:
  NonlinearNewmarkIntegrator(const SymmetricBandMatrix& mass, const SymmetricBandMatrix& stiffness,
                             RayleighDamping damping, NonlinearForce& force,
                             GeneralizedAlphaParameters parameters, double time_step,
                             NewtonOptions options = {})
      : mass_(mass),
        stiffness_(stiffness),
        damping_(damping),
        force_(force),
        p_(parameters),
        dt_(time_step),
        options_(options),
        tangent_(mass.size(), mass.bandwidth()),
        jacobian_(mass.size(), mass.bandwidth()) {
    RequirePositive("time_step", time_step);
    if (p_.IsExplicit()) {
      throw std::invalid_argument(
          "beta = 0: the nonlinear path needs an implicit member (beta > 0)");
    }
    const int n = mass.size();
    // Sizes the factor's buffers now (rank-one part included), so that no step allocates them.
    (void)factor_.Compute(mass, 1.0, Eigen::VectorXd::Zero(n));
    for (Eigen::VectorXd* v :
         {&d_, &v_, &a_, &f_, &d_new_, &v_new_, &a_new_, &d_mid_, &v_mid_, &residual_, &work_, &r_,
          &f_target_, &f_start_, &d_save_, &v_save_, &a_save_}) {
      v->setZero(n);
    }
  }

  /// State at t = 0: a0 solves M a0 = f0 - C v0 - K d0 - r(d0).
  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& f0) {
    d_ = d0;
    v_ = v0;
    f_ = f0;
    time_ = 0.0;
    r_.setZero();
    tangent_.Clear();
    if (!force_.Evaluate(d_, r_, tangent_)) return Status::kNonFinite;
    return InitialAcceleration(mass_, stiffness_, damping_, d0, v0, f0 - r_, a_);
  }

  /// Advances by dt to the load f_next. On failure the state stays at the step's start.
  [[nodiscard]] Status Step(const Eigen::VectorXd& f_next) {
    f_start_ = f_;
    f_target_ = f_next;
    d_save_ = d_;
    v_save_ = v_;
    a_save_ = a_;
    const double time_save = time_;
    const Status status = Advance(0.0, 1.0, 0);
    if (status == Status::kOk) {
      f_ = f_next;
    } else {  // a cut step may have got part of the way: return to the step's start
      d_ = d_save_;
      v_ = v_save_;
      a_ = a_save_;
      time_ = time_save;
    }
    return status;
  }

  const Eigen::VectorXd& displacement() const { return d_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  const Eigen::VectorXd& acceleration() const { return a_; }
  double time() const { return time_; }
  /// Newton iterations of the last step (all sub-steps), and how many times it was cut.
  int last_iterations() const { return last_iterations_; }
  int last_cuts() const { return last_cuts_; }

 private:
  // Advances the fraction [from, to] of the current step, cutting it in halves on failure.
  Status Advance(double from, double to, int depth) {
    if (depth == 0) last_iterations_ = last_cuts_ = 0;
    const Status status = Substep(from, to);
    if (status == Status::kOk) return status;
    if (depth >= options_.max_cuts) return status;
    ++last_cuts_;
    const double mid = 0.5 * (from + to);
    const Status first = Advance(from, mid, depth + 1);
    return first == Status::kOk ? Advance(mid, to, depth + 1) : first;
  }

  // One generalised-alpha step over [from, to] of the step, the load interpolated linearly.
  Status Substep(double from, double to) {
    const double h = (to - from) * dt_;
    const double am = p_.alpha_m, af = p_.alpha_f, beta = p_.beta, gamma = p_.gamma;
    // Where t_(n+1-af) of this sub-step falls within the step, for the load's interpolation.
    const double s = (1.0 - af) * to + af * from;
    // Predictor: d_(n+1) = d_n + h v_n + h^2 (1/2 - beta) a_n + beta h^2 a_(n+1), a_(n+1) = a_n.
    d_new_ = d_ + h * v_ + h * h * 0.5 * a_;
    const double ca = 1.0 / (beta * h * h);
    double reference = 0.0;
    for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
      ++last_iterations_;
      // a_(n+1), v_(n+1) from d_(n+1) by Newmark's relations.
      a_new_ = ca * (d_new_ - d_ - h * v_) - (0.5 / beta - 1.0) * a_;
      v_new_ = v_ + h * ((1.0 - gamma) * a_ + gamma * a_new_);
      d_mid_ = (1.0 - af) * d_new_ + af * d_;
      v_mid_ = (1.0 - af) * v_new_ + af * v_;
      r_.setZero();
      tangent_.Clear();
      if (!force_.Evaluate(d_mid_, r_, tangent_)) return Status::kNonFinite;
      // R = M a_(n+1-am) + C v_mid + K d_mid + r - f_mid, term by term for the scale.
      work_ = (1.0 - am) * a_new_ + am * a_;
      mass_.Multiply(work_, residual_);
      reference = residual_.norm();
      mass_.Multiply(v_mid_, work_);
      residual_ += damping_.mass * work_;
      reference += damping_.mass * work_.norm();
      stiffness_.Multiply(d_mid_, work_);
      residual_ += work_;
      reference += work_.norm();
      stiffness_.Multiply(v_mid_, work_);
      residual_ += damping_.stiffness * work_;
      reference += damping_.stiffness * work_.norm() + r_.norm();
      work_ = (1.0 - s) * f_start_ + s * f_target_;
      reference += work_.norm();
      residual_ += r_ - work_;
      if (!residual_.allFinite()) return Status::kNonFinite;
      if (residual_.norm() <= options_.residual_tolerance * reference) return Accept(h);
      // J = (1-am) ca M + (1-af) gamma/(beta h) C + (1-af)(K + dr/dd).
      const double cm = (1.0 - am) * ca + (1.0 - af) * gamma / (beta * h) * damping_.mass;
      const double ck = (1.0 - af) * (1.0 + gamma / (beta * h) * damping_.stiffness);
      jacobian_.mutable_data() =
          cm * mass_.data() + ck * stiffness_.data() + (1.0 - af) * tangent_.band().data();
      const Status factored = factor_.Compute(jacobian_, (1.0 - af) * tangent_.rank_one_scale(),
                                              tangent_.rank_one_vector());
      if (factored != Status::kOk) return factored;
      residual_ = -residual_;
      factor_.SolveInPlace(residual_);
      d_new_ += residual_;
      if (residual_.norm() <= options_.increment_tolerance * d_new_.norm()) {
        a_new_ = ca * (d_new_ - d_ - h * v_) - (0.5 / beta - 1.0) * a_;
        v_new_ = v_ + h * ((1.0 - gamma) * a_ + gamma * a_new_);
        return Accept(h);
      }
    }
    return Status::kNotConverged;
  }

  Status Accept(double h) {
    d_ = d_new_;
    v_ = v_new_;
    a_ = a_new_;
    time_ += h;
    return Status::kOk;
  }

  const SymmetricBandMatrix& mass_;
  const SymmetricBandMatrix& stiffness_;
  RayleighDamping damping_;
  NonlinearForce& force_;
  GeneralizedAlphaParameters p_;
  double dt_;
  NewtonOptions options_;
  double time_ = 0.0;
  int last_iterations_ = 0;
  int last_cuts_ = 0;
  ForceTangent tangent_;
  SymmetricBandMatrix jacobian_;
  BandRankOneCholesky factor_;
  Eigen::VectorXd d_, v_, a_, f_, d_new_, v_new_, a_new_, d_mid_, v_mid_, residual_, work_, r_,
      f_target_, f_start_, d_save_, v_save_, a_save_;
};

}  // namespace cosmems
