#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/initial_acceleration.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_safeguards.hpp"
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
/// Why a step is made the way it is, measured on the stretching microbridge of
/// bench/stretching_step_bench.cpp (planar, 40 elements, 117 unknowns, dt = T1/20 after a sudden
/// midspan load), where the first version took 29-32 us and 5.7 iterations a step:
/// - The predictor. Extrapolating with the old acceleration, d_n + h v_n + h^2/2 a_n, left the
///   first two corrections useless (residual still 0.99 of its scale, corrections 12 times the
///   displacement): the sudden load rings every mode, and the ones above what the step resolves,
///   which average acceleration leaves undamped, reverse their acceleration every step. Without
///   the a_n term (d_n + h v_n, or d_n) Newton takes 4.0 iterations, but resolved motion then
///   loses the Taylor predictor's accuracy: the same bridge swinging in its first mode at
///   dt = T1/400 took 2.8 iterations a step instead of 2.0. So the a_n term is weighted by the
///   share of a_n that persisted over the last step, fitted by least squares (Accept()): 4.0 and
///   2.3 iterations (plain Newton). Residuals then fall as 1, 1e-2, 1e-7, 1e-12 of their scale,
///   quadratically, with the round-off floor near 1e-13: the tolerances were never at fault.
///   Extrapolations from the last two or three steps measured no better.
/// - The factorisation, 2.7 of the 5.5 us an iteration took: the tangent barely moves once a
///   step is near its solution, or from the end of one step to the start of the next, so its
///   band part's factor is kept while it keeps working (NewtonOptions::reuse_contraction, and
///   below), and only the rank-one part is renewed each iteration (one more back-solve, made
///   together with the system's): 1.14 factorisations a step instead of 3, for 4.06 iterations
///   instead of 4.0 (the bridge swinging at dt = T1/400: 0.03 factorisations, 3.0 iterations).
/// - The kernels: the factorisation as L D L^T (1.3 us instead of 2.6), the band products by
///   columns (157 ns instead of 258) and the two back-solves together (0.48 us instead of 0.84).
/// A step now takes about 7.5 us: 2.0 in 12 band products (M, K and the force's G_0, 4 times),
/// 1.4 in the factorisation, 1.3 in the back-solves, 1.4 in this class's vector passes and 0.5
/// in the rest of the force.
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
    if (!(options.reuse_contraction >= 0.0 && options.reuse_contraction < 1.0)) {
      throw std::invalid_argument("reuse_contraction = " + FormatValue(options.reuse_contraction) +
                                  ": must lie in [0, 1)");
    }
    if (p_.IsExplicit()) {
      throw std::invalid_argument(
          "beta = 0: the nonlinear path needs an implicit member (beta > 0)");
    }
    const int n = mass.size();
    // Sizes the factor's buffers now (rank-one part included), so that no step allocates them.
    (void)factor_.Compute(mass, 1.0, Eigen::VectorXd::Zero(n));
    for (Eigen::VectorXd* v :
         {&d_,      &v_,      &a_,        &f_,      &d_new_,   &v_new_, &a_new_,
          &d_mid_,  &v_mid_,  &residual_, &work_,   &r_,       &f_mid_, &d_star_,
          &v_star_, &d_save_, &v_save_,   &a_save_, &r_start_, &r_save_}) {
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
    factor_valid_ = false;
    r_.setZero();
    tangent_.Clear();
    if (!force_.Evaluate(d_, r_, tangent_) ||
        (force_.HasViscousPart() && !force_.EvaluateViscous(d_, v_, 0.0, r_, tangent_))) {
      return Status::kNonFinite;
    }
    r_start_ = r_;
    force_.Commit(d_);
    return InitialAcceleration(mass_, stiffness_, damping_, d0, v0, f0 - r_, a_);
  }

  /// Advances by dt to the load f_next. On failure the state stays at the step's start.
  [[nodiscard]] Status Step(const Eigen::VectorXd& f_next) {
    f_target_ = &f_next;
    last_iterations_ = last_cuts_ = last_factorizations_ = 0;
    time_save_ = time_;
    auto substep = [this](double a, double b, int) { return Substep(a, b); };
    auto save = [this] {
      d_save_ = d_;
      v_save_ = v_;
      a_save_ = a_;
      r_save_ = r_start_;
    };
    // A failed part of the step is retried as two halves (the state at the step's start saved).
    const Status status =
        AdvanceInHalves(0.0, 1.0, 0, options_.max_cuts, force_, last_cuts_, substep, save);
    if (status == Status::kOk) {
      f_ = f_next;
    } else if (last_cuts_ > 0) {  // a cut step may have got part of the way: return to its start
      d_ = d_save_;
      v_ = v_save_;
      a_ = a_save_;
      r_start_ = r_save_;
      time_ = time_save_;
    }
    f_target_ = nullptr;
    return status;
  }

  const Eigen::VectorXd& displacement() const { return d_; }
  const Eigen::VectorXd& velocity() const { return v_; }
  const Eigen::VectorXd& acceleration() const { return a_; }
  double time() const { return time_; }
  /// Newton iterations of the last step (all sub-steps), how many of them factored the tangent,
  /// and how many times the step was cut.
  int last_iterations() const { return last_iterations_; }
  int last_factorizations() const { return last_factorizations_; }
  int last_cuts() const { return last_cuts_; }

 private:
  // One generalised-alpha step over [from, to] of the step, the load interpolated linearly.
  Status Substep(double from, double to) {
    const double h = (to - from) * dt_;
    const double am = p_.alpha_m, af = p_.alpha_f, beta = p_.beta, gamma = p_.gamma;
    const double ca = 1.0 / (beta * h * h);
    // Newmark's relations as a_(n+1) = ca (d_(n+1) - d*), v_(n+1) = v* + gamma h a_(n+1).
    d_star_ = d_ + h * v_ + ((0.5 - beta) * h * h) * a_;
    v_star_ = v_ + ((1.0 - gamma) * h) * a_;
    // The load at t_(n+1-af) of this sub-step, interpolated linearly within the step.
    const double s = (1.0 - af) * to + af * from;
    f_mid_ = (1.0 - s) * f_ + s * *f_target_;
    const double f_norm = f_mid_.norm();
    const bool damped = damping_.mass != 0.0 || damping_.stiffness != 0.0;
    // J = cm M + ck K + ct dr/dd (the damping C = dm M + dk K folded in).
    const double cm = (1.0 - am) * ca + (1.0 - af) * gamma / (beta * h) * damping_.mass;
    const double ck = (1.0 - af) * (1.0 + gamma / (beta * h) * damping_.stiffness);
    const double ct = 1.0 - af;
    const bool viscous = force_.HasViscousPart();
    // Predictor d_(n+1) = d_n + h v_n + persistence h^2/2 a_n (see the class comment).
    d_new_ = d_ + h * v_ + (persistence_ * 0.5 * h * h) * a_;
    a_new_ = ca * (d_new_ - d_star_);
    const int n = static_cast<int>(d_.size());
    double previous_norm = 0.0;
    int settles = 0;
    // Newton has converged for the force's present state: true if the force keeps it there;
    // otherwise (a contact multiplier updated, a node peeled off) Newton starts afresh.
    auto settled = [&](int& iteration) {
      if (force_.Settle(d_new_)) return true;
      ++settles;
      iteration = 0;
      factor_valid_ = false;  // the tangent changed with the state
      return false;
    };
    for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
      if (settles > options_.max_settles) break;
      ++last_iterations_;
      // x_(n+1-af) = (1-af) x_(n+1) + af x_n; plain Newmark (af = 0) uses d_(n+1) as it is.
      if (af != 0.0) d_mid_ = (1.0 - af) * d_new_ + af * d_;
      const Eigen::VectorXd& d_mid = af != 0.0 ? d_mid_ : d_new_;
      // Pulled back into the force's domain along the last increment, which residual_ holds.
      if (!EvaluateWithinDomain(force_, iteration == 1, d_new_, residual_, r_, tangent_,
                                [&] { a_new_ = ca * (d_new_ - d_star_); })) {
        return Status::kNonFinite;
      }
      if (viscous) {
        v_new_ = v_star_ + (gamma * h) * a_new_;
        if (!force_.EvaluateViscous(d_new_, v_new_, gamma / (beta * h), r_, tangent_)) {
          return Status::kNonFinite;
        }
      }
      // R = M a_(n+1-am) + C v_mid + K d_mid + r - f_mid, term by term for the scale.
      if (am != 0.0) {
        work_ = (1.0 - am) * a_new_ + am * a_;
        mass_.Multiply(work_, residual_);
      } else {
        mass_.Multiply(a_new_, residual_);
      }
      double reference = damped ? residual_.norm() : 0.0;
      if (damped) {  // C v_mid = dm M v_mid + dk K v_mid
        v_mid_ = (1.0 - af) * (v_star_ + (gamma * h) * a_new_) + af * v_;
        if (damping_.mass != 0.0) {
          mass_.Multiply(v_mid_, work_);
          residual_ += damping_.mass * work_;
          reference += damping_.mass * work_.norm();
        }
        if (damping_.stiffness != 0.0) {
          stiffness_.Multiply(v_mid_, work_);
          residual_ += damping_.stiffness * work_;
          reference += damping_.stiffness * work_.norm();
        }
      }
      stiffness_.Multiply(d_mid, work_);
      // R += K d_mid + r - f_mid and the sizes of the terms, in one pass over the vectors.
      double mass2 = 0.0, stiffness2 = 0.0, force2 = 0.0, norm2 = 0.0;
      for (int i = 0; i < n; ++i) {
        const double m = residual_[i], k = work_[i];
        const double r = af != 0.0 ? (1.0 - af) * r_[i] + af * r_start_[i] : r_[i];
        const double sum = m + k + r - f_mid_[i];
        mass2 += m * m;  // M a_(n+1-am) alone unless damping was added to it above
        stiffness2 += k * k;
        force2 += r * r;
        norm2 += sum * sum;
        residual_[i] = sum;
      }
      reference +=
          (damped ? 0.0 : std::sqrt(mass2)) + std::sqrt(stiffness2) + std::sqrt(force2) + f_norm;
      const double norm = std::sqrt(norm2);
      // A finite norm means finite entries (a NaN or infinity would carry into it).
      if (!std::isfinite(norm) && !residual_.allFinite()) return Status::kNonFinite;
      // How much the factor's last solve cut the residual decides whether it serves again.
      if (iteration > 1) factor_contraction_ = norm / previous_norm;
      const double tolerance = options_.residual_tolerance * reference;
      if (norm <= tolerance ||
          (iteration > 1 && NewtonOptions::StalledAtRoundOff(norm, previous_norm,
                                                             [&] { return RoundOff(d_mid); }))) {
        if (settled(iteration)) return Accept(h);
        continue;
      }
      previous_norm = norm;
      // The band part's factor is kept (for the same coefficients: a cut step changes h) while
      // its last solve cut the residual by reuse_contraction, and past the first iteration only
      // if a solve that cuts as much again ends the step: a kept factor contracts about as much
      // as its last solve did, where a fresh one converges quadratically, and an iteration
      // (residual and solve, 1.7 us on the bridge) costs more than a factorisation (1.3 us).
      // The first iteration starts next to d_n, where the last step's factor was made, so that
      // factor serves it about as well as a new one would.
      const bool keep = factor_valid_ && cm == factor_cm_ && ck == factor_ck_ && ct == factor_ct_ &&
                        factor_contraction_ <= options_.reuse_contraction &&
                        (iteration == 1 || factor_contraction_ * norm <= tolerance);
      // J delta = R, the rank-one part of the tangent always fresh.
      const double scale = ct * tangent_.rank_one_scale();
      const Eigen::VectorXd& u = tangent_.rank_one_vector();
      bool shifted = false;
      if (keep) {
        // A kept band may not carry the fresh rank-one part: then iterate again from this
        // d_(n+1), whose unchanged residual has the tangent refactored.
        if (factor_.SetRankOneAndSolve(scale, u, residual_) != Status::kOk) continue;
      } else {
        jacobian_.mutable_data() =
            cm * mass_.data() + ck * stiffness_.data() + ct * tangent_.band().data();
        ++last_factorizations_;
        factor_valid_ = factor_.ComputeBand(jacobian_) == Status::kOk;
        Status solved = Status::kOk;
        if (factor_valid_) {
          factor_cm_ = cm;
          factor_ck_ = ck;
          factor_ct_ = ct;
          solved = factor_.SetRankOneAndSolve(scale, u, residual_);
        } else {  // the band alone is not definite: the whole tangent may be (not kept)
          solved = factor_.ComputeWithIndefiniteBand(jacobian_, scale, u);
          if (solved == Status::kOk) factor_.SolveInPlace(residual_);
        }
        if (solved == Status::kNotPositiveDefinite) {
          solved = SolveShifted(cm, ck, ct, scale, u);
          shifted = solved == Status::kOk;
        }
        if (solved != Status::kOk) return solved;
      }
      // d_(n+1) -= delta, a_(n+1) with it, and the sizes of both for the increment test.
      double increment2 = 0.0, displacement2 = 0.0;
      for (int i = 0; i < n; ++i) {
        const double delta = residual_[i];
        const double d = d_new_[i] - delta;
        increment2 += delta * delta;
        displacement2 += d * d;
        d_new_[i] = d;
        a_new_[i] = ca * (d - d_star_[i]);
      }
      // A shifted solve moves less than Newton would: its small increment proves nothing.
      if (!shifted &&
          std::sqrt(increment2) <= options_.increment_tolerance * std::sqrt(displacement2) &&
          settled(iteration)) {
        return Accept(h);
      }
    }
    return Status::kNotConverged;
  }

  // Solves J delta = R with the mass term of J raised until J is definite, where J itself is
  // not: inside a snap (the Casimir or electrostatic force overtaking the beam's stiffness near
  // the substrate) the step's matrix with little mass in it turns indefinite. The raised mass
  // is that of a shorter step, so the iteration creeps the way a shorter step would, but it
  // solves this step's equations, whose solution exists where contact catches the beam; the step
  // is cut only if that fails. Never kept for a later iteration.
  Status SolveShifted(double cm, double ck, double ct, double scale, const Eigen::VectorXd& u) {
    factor_valid_ = false;
    for (double shift = cm / 64.0; shift <= kMaxMassShift * cm; shift *= 4.0) {
      jacobian_.mutable_data() =
          (cm + shift) * mass_.data() + ck * stiffness_.data() + ct * tangent_.band().data();
      ++last_factorizations_;
      if (factor_.Compute(jacobian_, scale, u) == Status::kOk) {
        factor_.SolveInPlace(residual_);
        return Status::kOk;
      }
    }
    return Status::kNotPositiveDefinite;
  }

  // The largest mass shift of SolveShifted, as a multiple of the step's own mass term: that of a
  // step 2^-10 as long, the depth of cutting it replaces.
  static constexpr double kMaxMassShift = 1048576.0;

  // The rounding error of the residual's stiffness products, K d_mid and the stiffness-
  // proportional damping's K v_mid (100 elements at 100 us steps stalled at 7e-9 of the
  // reference, a sixteenth of this bound).
  double RoundOff(const Eigen::VectorXd& d_mid) {
    double bound = stiffness_.ProductRoundOff(d_mid, work_);
    if (damping_.stiffness != 0.0) {
      bound += damping_.stiffness * stiffness_.ProductRoundOff(v_mid_, work_);
    }
    return bound;
  }

  // Takes d_new_ and a_new_ (consistent with it) as the state at the end of the sub-step.
  Status Accept(double h) {
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
  RayleighDamping damping_;
  NonlinearForce& force_;
  GeneralizedAlphaParameters p_;
  double dt_;
  NewtonOptions options_;
  double time_ = 0.0;
  double time_save_ = 0.0;
  double persistence_ = 1.0;  ///< theta of the predictor, fitted to the last step
  int last_iterations_ = 0;
  int last_factorizations_ = 0;
  int last_cuts_ = 0;
  ForceTangent tangent_;
  SymmetricBandMatrix jacobian_;
  BandRankOneCholesky factor_;
  // Whether the band factor exists, its coefficients, and ||R_new|| / ||R|| of its last solve.
  bool factor_valid_ = false;
  double factor_contraction_ = 1.0;
  double factor_cm_ = 0.0, factor_ck_ = 0.0, factor_ct_ = 0.0;
  const Eigen::VectorXd* f_target_ = nullptr;
  Eigen::VectorXd d_, v_, a_, f_, d_new_, v_new_, a_new_, d_mid_, v_mid_, residual_, work_, r_,
      f_mid_, d_star_, v_star_, d_save_, v_save_, a_save_, r_start_, r_save_;
};

}  // namespace cosmems
