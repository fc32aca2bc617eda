#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/linalg/symmetric_band_pair.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/initial_acceleration.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/newton_driver.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"
#include "cosmems/time/rayleigh_damping.hpp"

namespace cosmems {

/// The nonlinear path of the Newmark family: M a + C v + K d + r(d, v) = f, generalised-alpha
/// balance, Newton on d_(n+1) with the consistent tangent
///   J = (1-am)/(beta dt^2) M + (1-af) gamma/(beta dt) C
///       + (1-af) (K + dr/dd + gamma/(beta dt) dr/dv (d_(n+1), v_(n+1))),
/// r's velocity-dependent part (NonlinearForce::EvaluateViscous) taken at v_(n+1), which Newmark
/// ties to d_(n+1).
/// The nonlinear force enters the balance interpolated, (1-af) r(d_(n+1)) + af r(d_n), rather
/// than evaluated at the interpolated state (Erlicher, Bonaventura & Bursi 2002: the same order
/// and dissipation): a constraint force, contact, then holds the state at the end of the step,
/// where an evaluation at d_(n+1-af) would let the end overshoot the substrate by af/(1-af) of
/// the last approach.
/// A step whose Newton iterations fail (no convergence, non-finite values, a force outside its
/// domain) is retried as two half steps, recursively up to NewtonOptions::max_cuts; if even
/// that fails, the state is left at the start of the step and the status says why. Steps
/// allocate nothing. Implicit members only (beta > 0).
///
/// Newton follows NewtonDriver's protocol. Two choices make a step cheap:
/// - The predictor d_n + h v_n + theta h^2/2 a_n weights the old acceleration by the share of it
///   that persisted over the last step (fitted by least squares in Finish()): after a sudden load
///   the modes above what the step resolves reverse their acceleration every step, and the full
///   Taylor term would leave the first corrections useless, while resolved motion keeps its
///   accuracy.
/// - Where the prediction lets go of a contact that holds the step's start (a probe the structure
///   began to press into over the last step: NonlinearForce::LetsGo), Newton starts from the
///   step's start instead.
/// - The band part of the tangent's factor is kept while it keeps working (the tangent barely
///   moves near a step's solution and from one step to the next), and only the rank-one part is
///   renewed each iteration, solved together with the system.
/// doc/speed.md has the measurements behind both (bench/stretching_step_bench.cpp).
class NonlinearNewmarkIntegrator {
 public:
  NonlinearNewmarkIntegrator(const SymmetricBandMatrix& mass, const SymmetricBandMatrix& stiffness,
                             RayleighDamping damping, NonlinearForce& force,
                             GeneralizedAlphaParameters parameters, double time_step,
                             NewtonOptions options = {})
      : mass_(mass),
        stiffness_(stiffness),
        products_(mass, stiffness),
        damping_(damping),
        force_(force),
        p_(parameters),
        dt_(time_step),
        newton_((ValidateNewtonOptions(options), options)),
        tangent_(mass.size(), mass.bandwidth()),
        jacobian_(mass.size(), mass.bandwidth()),
        linear_(mass, stiffness, damping, parameters, time_step),
        round_off_ceiling_(2.0 * stiffness.ProductRoundOffFactor() *
                           stiffness.AbsoluteRowSumMax()) {
    RequirePositive("time_step", time_step);
    if (p_.IsExplicit()) {
      throw std::invalid_argument(
          "beta = 0: the nonlinear path needs an implicit member (beta > 0)");
    }
    const int n = mass.size();
    // Sizes the factor's buffers now (rank-one part included), so that no step allocates them.
    (void)factor_.Compute(mass, 1.0, Eigen::VectorXd::Zero(n));
    for (Eigen::VectorXd* v :
         {&d_,      &v_,        &a_,       &f_,      &d_new_,   &v_new_,   &a_new_,   &d_mid_,
          &v_mid_,  &residual_, &work_,    &r_,      &f_mid_,   &d_star_,  &v_star_,  &d_save_,
          &v_save_, &a_save_,   &r_start_, &r_save_, &scratch_, &elastic_, &d_before_}) {
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
    persistence_ = 1.0;
    newton_.ForgetFactor();
    r_.setZero();
    tangent_.Clear();
    if (!force_.Evaluate(d_, r_, tangent_) ||
        (force_.HasViscousPart() && !force_.EvaluateViscous(d_, v_, 0.0, r_, tangent_))) {
      return Status::kNonFinite;
    }
    r_start_ = r_;
    force_.Commit(d_);
    idle_ = force_.Idle(d_);
    streak_ = false;
    return InitialAcceleration(mass_, stiffness_, damping_, d0, v0, f0 - r_, a_);
  }

  /// Advances by dt to the load f_next. On failure the state stays at the step's start.
  [[nodiscard]] Status Step(const Eigen::VectorXd& f_next) {
    f_target_ = &f_next;
    newton_.stats() = {};
    if (idle_ && IdleStep(f_next)) {
      f_target_ = nullptr;
      return Status::kOk;
    }
    time_save_ = time_;
    auto substep = [this](double a, double b, int) { return Substep(a, b); };
    auto save = [this] {
      d_save_ = d_;
      v_save_ = v_;
      a_save_ = a_;
      r_save_ = r_start_;
    };
    const Status status = newton_.AdvanceInHalves(substep, save, [this] { force_.Revert(); });
    if (status == Status::kOk) {
      f_ = f_next;
      idle_ = force_.Idle(d_);
    } else if (newton_.stats().cuts > 0) {  // a cut step may have got part of the way: back
      d_ = d_save_;
      v_ = v_save_;
      a_ = a_save_;
      r_start_ = r_save_;
      time_ = time_save_;
    }
    f_target_ = nullptr;
    return status;
  }

  const Eigen::VectorXd& displacement() const { return streak_ ? linear_.displacement() : d_; }
  const Eigen::VectorXd& velocity() const { return streak_ ? linear_.velocity() : v_; }
  const Eigen::VectorXd& acceleration() const { return streak_ ? linear_.acceleration() : a_; }
  double time() const { return time_; }
  /// What the last step cost (all its sub-steps).
  const NewtonStats& last_stats() const { return newton_.stats(); }
  /// The next step factors afresh (BeamStepper::ForgetFactor).
  void ForgetFactor() { newton_.ForgetFactor(); }

 private:
  friend class NewtonDriver;

  // A step whose force is idle at its start and at the linear structure's step's end is that
  // step: the linear integrator's (its factor, one solve, no Newton), which holds the state while
  // the force stays idle. The equations are then met exactly (the force and its tangent vanish
  // around both ends), so Newton would end there too, to round-off. False, and this integrator
  // back at the step's start, when the end is not idle.
  bool IdleStep(const Eigen::VectorXd& f_next) {
    force_.StartStep();  // as Newton's steps do, so that both keep one history
    if (!streak_) {
      linear_.SetState(d_, v_, a_, f_);
      streak_ = true;
    }
    if (linear_.Step(f_next) == Status::kOk) {
      if (force_.Idle(linear_.displacement())) {
        force_.Commit(linear_.displacement());
        f_ = f_next;
        time_ += dt_;
        return true;
      }
      linear_.Undo();
    }
    d_ = linear_.displacement();  // the step's start, which Newton takes from here
    v_ = linear_.velocity();
    a_ = linear_.acceleration();
    r_start_.setZero();  // the force there: idle
    streak_ = false;
    return false;
  }

  // One generalised-alpha step over [from, to] of the step, the load interpolated linearly.
  Status Substep(double from, double to) {
    force_.StartStep();
    h_ = (to - from) * dt_;
    const double h = h_;
    const double am = p_.alpha_m, af = p_.alpha_f, beta = p_.beta, gamma = p_.gamma;
    ca_ = 1.0 / (beta * h * h);
    // Newmark's relations as a_(n+1) = ca (d_(n+1) - d*), v_(n+1) = v* + gamma h a_(n+1).
    d_star_ = d_ + h * v_ + ((0.5 - beta) * h * h) * a_;
    v_star_ = v_ + ((1.0 - gamma) * h) * a_;
    // The load at t_(n+1-af) of this sub-step, interpolated linearly within the step.
    const double s = (1.0 - af) * to + af * from;
    f_mid_ = (1.0 - s) * f_ + s * *f_target_;
    f_norm_ = f_mid_.norm();
    // J = cm M + ck K + ct dr/dd (the damping C = dm M + dk K folded in).
    cm_ = (1.0 - am) * ca_ + (1.0 - af) * gamma / (beta * h) * damping_.mass;
    ck_ = (1.0 - af) * (1.0 + gamma / (beta * h) * damping_.stiffness);
    ct_ = 1.0 - af;
    // Predictor d_(n+1) = d_n + h v_n + persistence h^2/2 a_n (see the class comment), or the
    // step's start where it would carry the structure off a contact holding it there.
    d_new_ = d_ + h * v_ + (persistence_ * 0.5 * h * h) * a_;
    if (force_.LetsGo(d_, d_new_)) d_new_ = d_;
    a_new_ = ca_ * (d_new_ - d_star_);
    // The factor serves the sub-steps of one length: the key is h.
    return newton_.Solve(*this, h);
  }

  // NewtonDriver's scheme: R = M a_(n+1-am) + C v_mid + K d_mid + r - f_mid, term by term for
  // the scale, with d_(n+1) the unknown; the force's tangent with it, or its rank-one part alone
  // (EvaluateResidual: the matrix deferred, EvaluateMatrix). EvaluateAtIterate fills the parts
  // of the tangent that tangent_ was cleared for.
  bool Evaluate(NewtonResidual& out) {
    tangent_.Clear();
    return EvaluateAtIterate(out);
  }
  bool EvaluateResidual(NewtonResidual& out) {
    tangent_.ClearRankOne();
    return EvaluateAtIterate(out);
  }
  // The force's whole tangent at the iterate EvaluateResidual() evaluated; its r, the same,
  // goes to a scratch vector.
  bool EvaluateMatrix() {
    tangent_.Clear();
    scratch_.setZero();
    if (!force_.Evaluate(d_new_, scratch_, tangent_)) return false;
    return !force_.HasViscousPart() ||
           force_.EvaluateViscous(d_new_, v_new_, p_.gamma / (p_.beta * h_), scratch_, tangent_);
  }
  bool EvaluateAtIterate(NewtonResidual& out) {
    const double am = p_.alpha_m, af = p_.alpha_f, gamma = p_.gamma, h = h_;
    r_.setZero();
    if (!force_.Evaluate(d_new_, r_, tangent_)) return false;
    // x_(n+1-af) = (1-af) x_(n+1) + af x_n; plain Newmark (af = 0) uses d_(n+1) as it is.
    if (af != 0.0) d_mid_ = (1.0 - af) * d_new_ + af * d_;
    const Eigen::VectorXd& d_mid = af != 0.0 ? d_mid_ : d_new_;
    if (force_.HasViscousPart()) {
      v_new_ = v_star_ + (gamma * h) * a_new_;
      if (!force_.EvaluateViscous(d_new_, v_new_, gamma / (p_.beta * h), r_, tangent_)) {
        out.norm = std::numeric_limits<double>::quiet_NaN();  // non-finite, not a retreat
        return true;
      }
    }
    // The damping C = dm M + dk K folded into the two band products, each the size of a term:
    // M (a_(n+1-am) + dm v_mid), the inertia's, and K (d_mid + dk v_mid), the elastic one's.
    work_ = (1.0 - am) * a_new_ + am * a_;
    const bool damped = damping_.mass != 0.0 || damping_.stiffness != 0.0;
    if (damped) v_mid_ = (1.0 - af) * (v_star_ + (gamma * h) * a_new_) + af * v_;
    if (damping_.mass != 0.0) work_ += damping_.mass * v_mid_;
    if (damping_.stiffness != 0.0) {
      elastic_ = d_mid + damping_.stiffness * v_mid_;
      products_.Multiply(work_, elastic_, residual_, work_);
    } else {
      products_.Multiply(work_, d_mid, residual_, work_);
    }
    // R = M (..) + K (..) + r - f_mid and the sizes of the terms, in one pass over the vectors.
    double mass2 = 0.0, stiffness2 = 0.0, force2 = 0.0, norm2 = 0.0;
    const int n = static_cast<int>(d_.size());
    for (int i = 0; i < n; ++i) {
      const double m = residual_[i], k = work_[i];
      const double r = af != 0.0 ? (1.0 - af) * r_[i] + af * r_start_[i] : r_[i];
      const double sum = m + k + r - f_mid_[i];
      mass2 += m * m;
      stiffness2 += k * k;
      force2 += r * r;
      norm2 += sum * sum;
      residual_[i] = sum;
    }
    out.reference = std::sqrt(mass2) + std::sqrt(stiffness2) + std::sqrt(force2) + f_norm_;
    out.norm = std::sqrt(norm2);
    return true;
  }

  // Back along the last correction, which residual_ still holds (d = previous - correction).
  bool Retreat() {
    residual_ *= 0.5;
    d_new_ += residual_;
    a_new_ = ca_ * (d_new_ - d_star_);
    return true;
  }
  // The predictor outside the force's domain: the step's start instead.
  bool BackToStart() {
    d_new_ = d_;
    a_new_ = ca_ * (d_new_ - d_star_);
    return true;
  }
  // The iterate before the last correction.
  bool Undo() {
    d_new_ = d_before_;
    a_new_ = ca_ * (d_new_ - d_star_);
    return true;
  }

  // The rounding error of the residual's stiffness product K (d_mid + dk v_mid) (100 elements at
  // 100 us steps stalled at 7e-9 of the reference, a sixteenth of this bound).
  double RoundOff() { return stiffness_.ProductRoundOff(RoundOffState(), work_); }
  // Twice the bound's ceiling (SymmetricBandMatrix::AbsoluteRowSumMax), so that neither's own
  // rounding can put the bound above it.
  double RoundOffCeiling() { return round_off_ceiling_ * RoundOffState().norm(); }
  // The state K multiplies in the residual.
  const Eigen::VectorXd& RoundOffState() const {
    if (damping_.stiffness != 0.0) return elastic_;
    return p_.alpha_f != 0.0 ? d_mid_ : d_new_;
  }

  // J delta = R with the kept band factor, the rank-one part of the tangent always fresh.
  Status SolveKept() {
    return factor_.SetRankOneAndSolve(ct_ * tangent_.rank_one_scale(), tangent_.rank_one_vector(),
                                      residual_);
  }

  // J delta = R with J's mass term raised by `shift`. Without a shift the band part is factored
  // alone (the factor the driver keeps) when it is definite; otherwise the whole tangent may be.
  NewtonFactor Factor(double shift) {
    const double scale = ct_ * tangent_.rank_one_scale();
    const Eigen::VectorXd& u = tangent_.rank_one_vector();
    jacobian_.mutable_data() =
        (cm_ + shift) * mass_.data() + ck_ * stiffness_.data() + ct_ * tangent_.band().data();
    NewtonFactor out;
    if (shift == 0.0 && factor_.ComputeBand(jacobian_) == Status::kOk) {
      out.reusable = true;
      out.status = factor_.SetRankOneAndSolve(scale, u, residual_);
      return out;
    }
    out.status = shift == 0.0 ? factor_.ComputeWithIndefiniteBand(jacobian_, scale, u)
                              : factor_.Compute(jacobian_, scale, u);
    if (out.status == Status::kOk) factor_.SolveInPlace(residual_);
    return out;
  }

  double MassTerm() const { return cm_; }

  // d_(n+1) -= delta, a_(n+1) with it, and the sizes of both for the increment test.
  NewtonCorrection Update() {
    double increment2 = 0.0, displacement2 = 0.0;
    for (int i = 0; i < d_new_.size(); ++i) {
      const double delta = residual_[i];
      d_before_[i] = d_new_[i];  // for Undo()
      const double d = d_new_[i] - delta;
      increment2 += delta * delta;
      displacement2 += d * d;
      d_new_[i] = d;
      a_new_[i] = ca_ * (d - d_star_[i]);
    }
    NewtonCorrection out;
    out.size = std::sqrt(increment2);
    out.iterate = std::sqrt(displacement2);
    return out;
  }

  bool Settle() { return force_.Settle(d_new_); }

  // Takes d_new_ and a_new_ (consistent with it) as the state at the end of the sub-step.
  Status Finish() {
    const double h = h_;
    // The share of a_n that persisted over the step, for the next predictor: the least-squares
    // theta of d_(n+1) - d_n - h v_n = theta h^2/2 a_n, within [0, 1].
    double along = 0.0, squared = 0.0;
    for (int i = 0; i < d_.size(); ++i) {
      along += (d_new_[i] - d_[i] - h * v_[i]) * a_[i];
      squared += a_[i] * a_[i];
    }
    const double fit = along / (0.5 * h * h * squared);
    persistence_ = std::isfinite(fit) ? std::clamp(fit, 0.0, 1.0) : 1.0;
    v_ = v_star_ + (p_.gamma * h) * a_new_;
    force_.ProjectMotion(d_new_, v_, a_new_);
    d_.swap(d_new_);  // swaps the buffers: allocates nothing
    a_.swap(a_new_);
    r_start_.swap(r_);  // r at the accepted state (at the last iterate, within the tolerance)
    time_ += h;
    force_.Commit(d_);
    return Status::kOk;
  }

  const SymmetricBandMatrix& mass_;
  const SymmetricBandMatrix& stiffness_;
  SymmetricBandPair products_;  ///< M and K side by side: the residual's two products in one pass
  RayleighDamping damping_;
  NonlinearForce& force_;
  GeneralizedAlphaParameters p_;
  double dt_;
  NewtonDriver newton_;
  double time_ = 0.0;
  double time_save_ = 0.0;
  double persistence_ = 1.0;  ///< theta of the predictor, fitted to the last step
  // The sub-step being solved: its length, Newmark's ca, J's coefficients and ||f_mid||.
  double h_ = 0.0, ca_ = 0.0, cm_ = 0.0, ck_ = 0.0, ct_ = 0.0, f_norm_ = 0.0;
  ForceTangent tangent_;
  SymmetricBandMatrix jacobian_;
  BandRankOneCholesky factor_;
  LinearNewmarkIntegrator linear_;  ///< the steps while the force is idle
  bool idle_ = false;               ///< whether the force is idle at the accepted state
  bool streak_ = false;             ///< whether linear_ holds the state (d_, v_, a_ do not)
  const Eigen::VectorXd* f_target_ = nullptr;
  double round_off_ceiling_;  ///< RoundOffCeiling() per unit of the state's norm
  Eigen::VectorXd d_, v_, a_, f_, d_new_, v_new_, a_new_, d_mid_, v_mid_, residual_, work_, r_,
      f_mid_, d_star_, v_star_, d_save_, v_save_, a_save_, r_start_, r_save_, scratch_, elastic_,
      d_before_;
};

}  // namespace cosmems
