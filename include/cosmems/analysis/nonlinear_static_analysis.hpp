#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cosmems/analysis/static_analysis.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_case.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/time/newton_driver.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

struct NonlinearStaticOptions {
  NewtonOptions newton;
  /// A load step that fails is halved; below this fraction of the full load the solve gives up
  /// (Status::kNotConverged), keeping the last converged state.
  double min_load_step = 1.0 / 1024.0;
  /// Backtracking halvings of a Newton correction before it is taken whole anyway.
  int max_line_search = 8;
  /// Where the first load step's Newton starts (reduced, internal units); empty: the unloaded
  /// beam. A beam pressed onto the substrate starts there, say.
  Eigen::VectorXd start;
};

struct NonlinearStaticSolution {
  Status status = Status::kOk;
  Eigen::VectorXd displacement;  ///< reduced, internal units; the last converged state on failure
  double load_factor = 0.0;      ///< the share of the load carried: 1 when solved
  int iterations = 0;            ///< Newton corrections over all load steps
  int load_steps = 0;            ///< accepted load steps
  NewtonStats stats;             ///< what the solve cost, the load-step halvings as cuts
};

/// Statics with a nonlinear internal force: K d + r(d) + lambda r_s(d) = lambda f, lambda from
/// 0 to 1, r_s an optional stateless force ramped with the loads (surface pressures, which leave no
/// unloaded equilibrium to start from; a fold of the ramp stops the load steps there).
///
/// Adaptive load stepping (NewtonDriver::RampLoad): a step that Newton solves doubles the next
/// one (up to what remains), one that fails is retried at half the size from the last converged
/// state. Newton (NewtonDriver) uses the force's consistent tangent (band plus rank-one),
/// factored afresh at every iteration, and a backtracking line search on the residual norm, so a
/// correction that overshoots a stiffening force is shortened instead of thrown away. Converged
/// on NewtonOptions' relative residual or increment.
/// `stiffness`: the linear structure's K (a beam's or a frame's), which must outlive the solve.
class NonlinearStaticSolve : private PlainNewtonScheme {
 public:
  NonlinearStaticSolve(const SymmetricBandMatrix& stiffness, NonlinearForce& force,
                       const NonlinearStaticOptions& options, NonlinearForce* ramped)
      : k_(stiffness), force_(force), ramped_(ramped), options_(options), newton_(options.newton) {
    const int n = stiffness.size();
    tangent_ = ForceTangent(n, k_.bandwidth());
    ramped_tangent_ = ForceTangent(n, k_.bandwidth());
    jacobian_ = SymmetricBandMatrix(n, k_.bandwidth());
    for (Eigen::VectorXd* v : {&rs_, &d_, &r_, &residual_, &step_, &trial_, &kd_}) v->setZero(n);
  }

  NonlinearStaticSolution Solve(const Eigen::VectorXd& f) {
    f_ = &f;
    NonlinearStaticSolution out;
    out.displacement = Eigen::VectorXd::Zero(d_.size());
    if (options_.start.size() == d_.size()) out.displacement = options_.start;
    auto attempt = [&](double target) {
      d_ = out.displacement;
      lambda_ = target;
      stale_ = true;
      return newton_.Solve(*this, std::numeric_limits<double>::quiet_NaN());
    };
    auto accept = [&] {
      force_.Commit(d_);
      out.displacement = d_;
      ++out.load_steps;
    };
    out.status = newton_.RampLoad(1.0, options_.min_load_step, out.load_factor, attempt, accept,
                                  [&] { force_.Revert(); });
    out.iterations = newton_.stats().iterations;
    out.stats = newton_.stats();
    return out;
  }

 private:
  friend class NewtonDriver;

  // R(x) = K x + r(x) - lambda f into residual_, and the size of the terms it balances.
  bool EvaluateAt(const Eigen::VectorXd& x) {
    r_.setZero();
    tangent_.Clear();
    if (!force_.Evaluate(x, r_, tangent_)) return false;
    if (ramped_) {
      rs_.setZero();
      ramped_tangent_.Clear();
      if (!ramped_->Evaluate(x, rs_, ramped_tangent_)) return false;
      r_ += lambda_ * rs_;
      tangent_.band().mutable_data() += lambda_ * ramped_tangent_.band().data();
    }
    k_.Multiply(x, kd_);
    residual_ = kd_ + r_ - lambda_ * *f_;
    reference_ = kd_.norm() + r_.norm() + lambda_ * f_->norm();
    return residual_.allFinite();
  }

  // NewtonDriver's scheme. The line search of the last Update() evaluated the iterate already.
  bool Evaluate(NewtonResidual& out) {
    if (stale_) {
      evaluated_ = EvaluateAt(d_);
      stale_ = false;
    }
    out.norm = residual_.norm();
    out.reference = reference_;
    return evaluated_;
  }
  // kd_ serves as the bound's work vector: the next evaluation forms K d again.
  double RoundOff() { return k_.ProductRoundOff(d_, kd_); }
  NewtonFactor Factor(double /*shift*/) {
    jacobian_.mutable_data() = k_.data() + tangent_.band().data();
    NewtonFactor out;
    out.status = factor_.Compute(jacobian_, tangent_.rank_one_scale(), tangent_.rank_one_vector());
    if (out.status == Status::kOk) {
      step_ = -residual_;
      factor_.SolveInPlace(step_);
    }
    return out;
  }
  // Backtracks along the correction while the residual does not fall, and takes the last trial
  // after max_line_search halvings whatever it gives.
  NewtonCorrection Update() {
    const double norm = residual_.norm();
    double alpha = 1.0;
    for (int cut = 0;; ++cut) {
      trial_ = d_ + alpha * step_;
      evaluated_ = EvaluateAt(trial_);
      if ((evaluated_ && residual_.norm() < (1.0 - 1e-4 * alpha) * norm) ||
          cut == options_.max_line_search) {
        break;
      }
      alpha *= 0.5;
    }
    d_ = trial_;
    NewtonCorrection out;
    if (!residual_.allFinite()) out.status = Status::kNonFinite;
    out.size = alpha * step_.norm();
    out.iterate = d_.norm();
    return out;
  }
  // Converged for the force's present state; a force that changes it there starts Newton afresh.
  bool Settle() {
    if (force_.Settle(d_)) return true;
    stale_ = true;
    return false;
  }
  Status Finish() { return Status::kOk; }

  const SymmetricBandMatrix& k_;
  NonlinearForce& force_;
  NonlinearForce* ramped_;
  NonlinearStaticOptions options_;  // a copy: callers pass temporaries
  NewtonDriver newton_;
  ForceTangent tangent_, ramped_tangent_;
  SymmetricBandMatrix jacobian_;
  BandRankOneCholesky factor_;
  const Eigen::VectorXd* f_ = nullptr;
  Eigen::VectorXd rs_, d_, r_, residual_, step_, trial_, kd_;
  double lambda_ = 0.0, reference_ = 0.0;
  bool stale_ = true, evaluated_ = false;
};

template <int Dim>
NonlinearStaticSolution SolveNonlinearStatic(const BeamModel<Dim>& model, NonlinearForce& force,
                                             const LoadCase& loads,
                                             const NonlinearStaticOptions& options = {},
                                             NonlinearForce* ramped = nullptr) {
  NonlinearStaticSolve solve(model.Stiffness(), force, options, ramped);
  return solve.Solve(AssembleLoads(model, loads));
}

}  // namespace cosmems
