#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/rod/block_tridiagonal_system.hpp"
#include "cosmems/rod/cosserat_options.hpp"
#include "cosmems/rod/cosserat_rod.hpp"
#include "cosmems/rod/rod_loads.hpp"
#include "cosmems/rod/rod_state.hpp"
#include "cosmems/time/newton_driver.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

/// Options of the static Cosserat solve.
struct CosseratStaticOptions {
  /// Relative tolerances and the iterations allowed per load step (see NewtonOptions and
  /// RodNewtonOptions).
  /// max_cuts bounds the halvings of a load step: the smallest step is
  /// first_load_step / 2^max_cuts.
  NewtonOptions newton = RodNewtonOptions();
  /// The first increment of the load factor, as a fraction of the load change, in (0, 1]. 1 tries
  /// the whole change at once (a haptic re-solve); smaller values start a large load gently.
  double first_load_step = 1.0;
  /// Halvings of a Newton step by the line search before the load step is declared failed.
  int max_line_search = 4;

  void Validate() const {
    ValidateNewtonOptions(newton);
    RequireWithin("first_load_step", first_load_step, 1e-12, 1.0);
    RequireWithin("max_line_search", max_line_search, 0, 60);
  }
};

/// Static equilibrium of a Cosserat rod: Newton's method on f_int(x) = f_ext(x) with the
/// consistent tangent, rotations updated multiplicatively (R <- exp(theta^) R), adaptive load
/// stepping and a line search.
///
/// - Load stepping: the load moves from the last converged one to the requested one along a
///   straight path in steps of the load factor; a step whose Newton iterations fail is halved
///   (from the last converged state), a step that succeeds lets the next one double.
/// - Line search: a Newton step is halved while the tangent at the trial state is not positive
///   definite (or anything there is not finite), i.e. while the step leaves the region where
///   the rod is stable, from which Newton would head for a saddle or another branch. The trial's
///   factorisation is the next iteration's, so an accepted step costs nothing extra. A
///   monotone merit (energy or residual norm) is the wrong guard for a slender rod: the stiff
///   axial force dominates both, and the first steps of a large load change raise it before
///   the iteration converges (reference cantilever, tip load 2.5 EI/L^2 from rest: residual
///   2.5 -> 3.0 -> 1.4 -> ... -> 1e-9 in six iterations; with the plain position update,
///   which CosseratRod::Retract replaces, 0.5 EI/L^2 already gave 0.5 -> 3.7e3).
/// - Convergence: |r| <= residual_tolerance (|f_ext| + (sum |g_e|^2)^(1/2)), the residual against
///   the loads and element forces it balances, or |dx| <= increment_tolerance |x| (RodState::Size).
/// - Warm start: every Solve() starts from the current state and the loads it balances, so a
///   small load change (a haptic tick) costs one load step of a few iterations.
///
/// On failure the state returns to where Solve() started and the status says why. Solve()
/// allocates nothing and throws nothing once the solver is built.
class CosseratStaticSolver : private PlainNewtonScheme {
 public:
  explicit CosseratStaticSolver(const CosseratRod& rod, CosseratStaticOptions options = {})
      : rod_(rod),
        options_((options.Validate(), options)),
        state_(rod.UndeformedState()),
        trial_(state_),
        saved_(state_),
        start_(state_),
        system_(rod.MakeSystem()),
        correction_(3, rod.NodeCount()),
        kinematics_(rod.MakeKinematics()),
        newton_(options.newton) {
    for (RodLoads* loads : {&converged_loads_, &start_loads_, &target_loads_, &loads_}) {
      *loads = RodLoads::None(rod.NodeCount());
    }
    for (Eigen::VectorXd* v : {&internal_force_, &residual_, &increment_}) {
      v->setZero(rod.DofCount());
    }
  }

  /// Equilibrium under `loads` (SI; dead forces one column per node), starting from the current
  /// state. Returns kOk, or the status of the last failed attempt once the load step has been
  /// halved max_cuts times (the state is then the one Solve() started from).
  [[nodiscard]] Status Solve(const RodLoads& loads) {
    assert(loads.dead_forces.cols() == rod_.NodeCount());
    rod_.ToInternal(loads, target_loads_);
    start_loads_ = converged_loads_;
    start_ = state_;
    newton_.stats() = {};
    last_load_steps_ = 0;
    auto attempt = [this](double factor) {
      RodLoads::Interpolate(start_loads_, target_loads_, factor, loads_);
      saved_ = state_;
      start_of_solve_ = true;
      return newton_.Solve(*this, std::numeric_limits<double>::quiet_NaN());
    };
    auto reject = [this] {
      std::swap(state_, saved_);
      internal_valid_ = false;
    };
    double reached = 0.0;
    const Status status = newton_.RampLoad(
        options_.first_load_step, std::ldexp(options_.first_load_step, -options_.newton.max_cuts),
        reached, attempt, [this] { ++last_load_steps_; }, reject);
    if (status != Status::kOk) {
      state_ = start_;
      return status;
    }
    converged_loads_ = target_loads_;
    return Status::kOk;
  }

  /// Back to the undeformed, unloaded rod.
  void Reset() {
    state_ = rod_.UndeformedState();
    converged_loads_ = RodLoads::None(rod_.NodeCount());
    internal_valid_ = false;
  }

  const CosseratRod& rod() const { return rod_; }
  /// The current equilibrium (internal units; see CosseratRod for outputs in SI).
  const RodState& state() const { return state_; }
  /// What the last Solve() cost (its load-step halvings as cuts), and its load steps.
  const NewtonStats& last_stats() const { return newton_.stats(); }
  int last_load_steps() const { return last_load_steps_; }

 private:
  friend class NewtonDriver;

  // NewtonDriver's scheme at loads_ from state_. A line search's trial leaves the residual and
  // the factor at the next iterate.
  bool Evaluate(NewtonResidual& out) {
    if (start_of_solve_) {
      if (!internal_valid_) EvaluateInternal(state_);
      reference_ = ApplyLoads(state_);
      factored_ = false;
      start_of_solve_ = false;
    }
    out.norm = residual_.norm();
    out.reference = reference_;
    return true;
  }
  NewtonFactor Factor(double /*shift*/) {
    NewtonFactor out;
    out.fresh = !factored_;
    if (!factored_) out.status = Factorize();
    if (out.status != Status::kOk) return out;
    increment_ = -residual_;
    system_.SolveInPlace(increment_);
    return out;
  }
  // A negligible correction is taken whole and ends the solve. Otherwise it is halved while the
  // tangent at the trial state is not positive definite or anything there is not finite (see
  // the class comment); the trial's factorisation serves the next iteration.
  NewtonCorrection Update() {
    NewtonCorrection out;
    out.size = increment_.norm();
    out.iterate = state_.Size();
    if (out.size <= options_.newton.increment_tolerance * out.iterate) {
      rod_.Retract(state_, increment_, 1.0, trial_, correction_);
      std::swap(state_, trial_);
      internal_valid_ = false;
      return out;
    }
    double step = 1.0;
    for (int halving = 0;; ++halving) {
      rod_.Retract(state_, increment_, step, trial_, correction_);
      EvaluateInternal(trial_);
      reference_ = ApplyLoads(trial_);
      const double trial_norm = residual_.norm();
      Status status = std::isfinite(trial_norm) ? Status::kOk : Status::kNonFinite;
      factored_ = false;
      if (status == Status::kOk && trial_norm > options_.newton.residual_tolerance * reference_) {
        status = Factorize();  // kept for the next iteration when the step is taken
        ++out.factorizations;
        factored_ = status == Status::kOk;
      }
      if (status == Status::kOk) break;
      if (halving == options_.max_line_search) {
        internal_valid_ = false;  // the caches hold the rejected trial
        out.status = status;
        return out;
      }
      step *= 0.5;
    }
    std::swap(state_, trial_);
    return out;
  }
  Status Finish() { return Status::kOk; }

  // Internal forces at `s`, kept while the state does not change; the tangent follows on demand.
  void EvaluateInternal(const RodState& s) {
    internal_size_ = rod_.InternalForces(s, internal_force_, kinematics_);
    internal_valid_ = true;
    tangent_valid_ = false;
  }

  // Factors the Newton matrix at the state of the last EvaluateInternal(), assembling the
  // elements' tangent first unless it is there already (it stays valid across load changes;
  // the load stiffness is ApplyLoads()'s).
  Status Factorize() {
    if (!tangent_valid_) {
      rod_.InternalTangent(kinematics_, system_);
      tangent_valid_ = true;
    }
    return system_.Factorize();
  }

  // residual_ = f_int - f_ext(loads_) with the load stiffness; returns the residual's reference.
  double ApplyLoads(const RodState& s) {
    residual_ = internal_force_;
    const double load_size = rod_.SubtractLoads(s, loads_, residual_, &system_);
    rod_.ClearSupported(residual_);
    return internal_size_ + load_size;
  }

  const CosseratRod& rod_;
  CosseratStaticOptions options_;
  RodState state_, trial_, saved_, start_;
  RodLoads converged_loads_, start_loads_, target_loads_, loads_;
  BlockTridiagonalSystem system_;
  Eigen::VectorXd internal_force_, residual_, increment_;
  Eigen::Matrix3Xd correction_;  // workspace of CosseratRod::Retract
  double internal_size_ = 0.0;
  CosseratRod::ElementKinematics kinematics_;
  NewtonDriver newton_;
  double reference_ = 0.0;  // the size of the terms the residual balances
  bool internal_valid_ = false;
  bool tangent_valid_ = false;
  bool start_of_solve_ = true;  // the next Evaluate() starts a Newton solve at state_
  bool factored_ = false;       // system_ holds the factor at state_ (from a line search)
  int last_load_steps_ = 0;
};

}  // namespace cosmems
