#pragma once

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "cosmems/core/status.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

/// The size of a residual, of the terms it balances, and whether the side conditions of a
/// bordered system (a pull-in path's imposed travel) hold.
struct NewtonResidual {
  double norm = 0.0;
  double reference = 0.0;
  bool side_conditions_met = true;
};

/// A Newton matrix factored and the correction solved with it: `reusable` lets the driver keep
/// the factor for later iterations and steps; `fresh` is false where the scheme had the factor
/// already (a line search made it at the iterate).
struct NewtonFactor {
  Status status = Status::kOk;
  bool reusable = false;
  bool fresh = true;
};

/// A correction applied: its size against the iterate's (the increment test), and the
/// factorisations a line search made on the way.
struct NewtonCorrection {
  Status status = Status::kOk;
  double size = std::numeric_limits<double>::infinity();
  double iterate = 0.0;
  int factorizations = 0;
};

/// The hooks of NewtonDriver's scheme for a scheme without use for them: no retreat (no force
/// with a bounded domain), no undo, no stall test, no kept factor, no mass term to raise, no
/// force state to settle. A scheme derives from it (privately, the driver its friend) and
/// defines the rest.
class PlainNewtonScheme {
 public:
  bool Retreat() { return false; }
  bool BackToStart() { return false; }
  bool Undo() { return false; }
  double RoundOff() { return 0.0; }
  double RoundOffCeiling() { return std::numeric_limits<double>::infinity(); }
  Status SolveKept() { return Status::kNotConverged; }  // asked only for a NaN key: never
  double MassTerm() const { return 0.0; }
  bool Settle() { return true; }
};

/// The Newton protocol every nonlinear solve of the library follows: the generalised-alpha step
/// on the full model, the modal step with the held force, the Cosserat rod's step on the rotation
/// group, and the static, pull-in and rod equilibria. A scheme supplies its residual, matrix,
/// solve and update; the driver owns what happens between them and counts it (stats()):
///
/// - Convergence: ||R|| <= residual_tolerance * reference, or, past the first correction, a
///   residual within the rounding error of the products that form it (RoundOff), below which no
///   iteration can take it, or a correction below increment_tolerance of the iterate (a kept
///   factor's below predicted_increment_tolerance, where the contraction that factor last showed
///   predicts the residual within the tolerance: the haptic ticks'); then the
///   scheme's forces may change their state (Settle: a contact multiplier updated, a node peeled
///   off), and Newton starts afresh. A fine mesh meets the rounding test above the tolerance:
///   its K d is a small difference of large products (SymmetricBandMatrix::ProductRoundOff). The
///   bound costs a product as large as the residual's, so it is formed once a solve, at the
///   first iterate the tolerance does not end whose residual is within the scheme's ceiling of
///   the bound (RoundOffCeiling, a norm of K times one of d: a landing's residuals, hundreds of
///   tolerances, are far above it); the iterates after it differ from that one by corrections
///   too small to change it.
/// - The iterate outside a force's domain (a gap closed under a 1/gap^n pressure) is pulled back
///   along its last correction, halving it up to 10 times. The first iterate, the scheme's
///   prediction, is replaced by the state it predicted from (a step's start, inside the domain):
///   a predictor that carries an impact's velocity through the substrate then costs one
///   evaluation instead of a cut step. (Halving the prediction instead left Newton starting just
///   inside the domain, where a Casimir force's stiffness is largest: a step there failed with
///   the matrix indefinite at every mass shift.)
/// - The factor of the Newton matrix is kept, for the same matrix family (`key`, a step's
///   length), while its last solve cut the residual by NewtonOptions::reuse_contraction and,
///   past a solve's first iteration, another such cut would end it: a kept factor contracts
///   about as much as its last solve did, where a fresh one converges quadratically, and an
///   iteration costs more than a factorisation on a beam. The residual is exact either way. A
///   solve that took the residual to its rounding floor counts as a full contraction: the floor,
///   not the factor, stopped it, so the factor serves the next step (on a fine mesh every step
///   would otherwise refactor).
/// - A kept factor's correction that takes the iterate outside a force's domain, or leaves the
///   residual more than a thousand times larger than it found it, is undone (Undo), and the
///   iteration factors afresh where it started: the stale factor went astray, not Newton, and a
///   fresh factor from far out may not find the way back (on a landing's jump in stiffness,
///   measured: 38 corrections, 48 factorisations and two cut steps in one haptic tick, where the
///   undone correction costs one evaluation). A smaller growth is left to Newton (kUndoGrowth).
///   This is what lets the haptic steps keep a factor on a looser contraction
///   (HapticPhysicsOptions::reuse_contraction).
/// - Where the kept factor is expected to serve (kept for this key, its last solve contracting
///   enough), a scheme that can defer its matrix evaluates the residual alone, and the matrix
///   only if the iteration factors after all: the matrix is the surface forces' quadrature of
///   their tangent and a pass over the whole band, as dear as the residual, and unused by a kept
///   factor. The iterates are the same either way.
/// - A matrix that is not definite (inside a Casimir or electrostatic snap) is factored again
///   with its mass term raised, up to that of a step 2^-10 as long: the iteration creeps the way
///   a shorter step would but solves this step's equations. A raised factor is never kept, and
///   its small correction proves nothing.
/// - A time step that fails is retried as two halves, recursively (AdvanceInHalves); a load step
///   that fails is halved from the last converged state (RampLoad).
///
/// A scheme provides:
///   bool Evaluate(NewtonResidual&)  residual and matrix at the iterate; false outside the domain
///   bool Retreat()                  iterate moved back by half its last correction; false: none
///   bool BackToStart()              the first iterate replaced by where it was predicted from;
///                                   false: none
///   bool Undo()                     the iterate back to where the last correction started;
///                                   false: none
///   double RoundOff()               the residual's rounding bound (0: no stall test)
///   double RoundOffCeiling()        a bound at least RoundOff()'s, costing no pass over the
///                                   matrix (infinity: none)
///   Status SolveKept()              the correction with the kept factor
///   NewtonFactor Factor(double shift)  factors the matrix (+ shift times the mass) and solves
///   double MassTerm()               the matrix's mass coefficient (0: nothing to raise)
///   NewtonCorrection Update()       applies the correction
///   bool Settle()                   the forces keep their state at the converged iterate
///   Status Finish()                 takes the converged iterate
/// and, to defer its matrix to the iterations that factor (above), both of
///   bool EvaluateResidual(NewtonResidual&)  as Evaluate, the matrix left out
///   bool EvaluateMatrix()                   the matrix at the iterate last evaluated
/// Nothing here allocates.
class NewtonDriver {
 public:
  explicit NewtonDriver(NewtonOptions options = {}) : options_(options) {}

  const NewtonOptions& options() const { return options_; }
  NewtonStats& stats() { return stats_; }
  const NewtonStats& stats() const { return stats_; }
  /// Forgets the kept factor (a new start, a changed matrix).
  void ForgetFactor() { key_ = kNoFactor; }

  /// Newton from the scheme's current iterate. `key` names the matrix family the kept factor
  /// serves (NaN: never keep).
  template <typename Scheme>
  Status Solve(Scheme& scheme, double key) {
    const Status status = Iterate(scheme, key);
    if (status != Status::kOk) {
      ++stats_.failures;
      ForgetFactor();
    }
    return status;
  }

  /// Advances the fraction [0, 1] of a time step by `substep(from, to, depth)`, depth being how
  /// many times the step was halved to get there, and retries a failed part as two halves,
  /// recursively up to max_cuts deep. After each failure `revert()` returns the forces to their
  /// last committed state; before the first cut `save()` keeps the state at the step's start,
  /// which a failed part leaves alone, for the caller to return to if even the cuts fail.
  template <typename Substep, typename Save, typename Revert>
  Status AdvanceInHalves(Substep&& substep, Save&& save, Revert&& revert) {
    return Halves(0.0, 1.0, 0, substep, save, revert);
  }

  /// Carries a load factor from 0 to 1: `attempt(target)` solves at the factor `target` from the
  /// last converged state, `accept()` takes it and `reject()` returns to that state. The first
  /// increment is `first`; one that succeeds doubles the next (up to what remains), one that
  /// fails is halved, down to `smallest`, below which the ramp gives up with the last failure's
  /// status. `reached` is the factor carried.
  template <typename Attempt, typename Accept, typename Reject>
  Status RampLoad(double first, double smallest, double& reached, Attempt&& attempt,
                  Accept&& accept, Reject&& reject) {
    reached = 0.0;
    double increment = first;
    while (reached < 1.0) {
      const double target = std::fmin(1.0, reached + increment);
      const Status status = attempt(target);
      if (status == Status::kOk) {
        accept();
        reached = target;
        increment = std::fmin(2.0 * increment, 1.0 - reached);
        continue;
      }
      reject();
      increment *= 0.5;
      if (increment < smallest) return status;
      ++stats_.cuts;
    }
    return Status::kOk;
  }

 private:
  static constexpr double kNoFactor = std::numeric_limits<double>::quiet_NaN();
  // The largest mass shift, as a multiple of the matrix's own mass term: that of a step 2^-10 as
  // long, the depth of cutting it replaces.
  static constexpr double kMaxMassShift = 1048576.0;
  // How much larger a kept factor's correction may leave the residual before it is undone: a
  // stale factor that ran astray (a landing's jump in stiffness, measured: 4e4 times), not one
  // whose iterate Newton finds its way from (a Casimir press onto a contact plane 1 nm off the
  // substrate, OneNanometreGapTest: up to 21 times, and the step's start left the matrix
  // indefinite under every mass shift).
  static constexpr double kUndoGrowth = 1000.0;
  // The share of the tolerance a predicted residual must lie within (Predicted).
  static constexpr double kPredictionMargin = 0.1;

  template <typename Scheme>
  Status Iterate(Scheme& scheme, double key) {
    double previous = 0.0;
    double round_off = -1.0;  // the residual's rounding bound, once formed (-1: not yet)
    int settles = 0;
    bool kept = false;  // whether the last correction was the kept factor's
    // Newton has converged for the forces' present state: true if they keep it; otherwise Newton
    // starts afresh (the matrix changed with the state).
    auto settled = [&](int& iteration) {
      if (scheme.Settle()) return true;
      ++settles;
      iteration = -1;
      round_off = -1.0;  // the iterate may move far under the new state
      ForgetFactor();
      return false;
    };
    // At most max_iterations evaluations, each followed by a correction unless it converged (a
    // force's change of state starts the count afresh).
    for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
      if (settles > options_.max_settles) return Status::kNotConverged;
      ++stats_.evaluations;
      NewtonResidual r;
      bool deferred = DefersMatrix<Scheme>() && KeptMayServe(key);
      bool undone = false;
      if (!EvaluateWithinDomain(scheme, iteration, settles, kept, deferred, undone, r)) {
        return Status::kNonFinite;
      }
      // A kept factor's correction that threw the residual up: back to where it started, to
      // factor afresh there (the stale factor's step, not Newton's, went astray).
      if (!undone && kept && iteration > 0 && r.norm > kUndoGrowth * previous && scheme.Undo()) {
        ++stats_.evaluations;
        deferred = false;
        if (!scheme.Evaluate(r)) return Status::kNonFinite;  // evaluated there before
        undone = true;
      }
      kept = false;
      if (undone) ForgetFactor();
      if (!std::isfinite(r.norm)) return Status::kNonFinite;
      if (iteration > 0) {
        contraction_ = r.norm / previous;
        unmeasured_ = 0;
      }
      const double tolerance = options_.residual_tolerance * r.reference;
      bool at_floor = false;
      if (r.norm > tolerance && iteration > 0) {
        if (round_off < 0.0 && r.norm <= scheme.RoundOffCeiling()) round_off = scheme.RoundOff();
        at_floor = r.norm <= round_off;  // never while unformed (-1)
      }
      if ((r.norm <= tolerance || at_floor) && r.side_conditions_met) {
        if (at_floor) contraction_ = 0.0;
        if (settled(iteration)) return scheme.Finish();
        continue;
      }
      previous = r.norm;
      const bool keep = KeptMayServe(key) && (iteration == 0 || contraction_ * r.norm <= tolerance);
      bool shifted = false;
      if (keep) {
        // A kept factor may not serve the fresh matrix (its rank-one part): iterate again from
        // this iterate with a new one.
        if (scheme.SolveKept() != Status::kOk) {
          ForgetFactor();
          continue;
        }
      } else {
        if constexpr (DefersMatrix<Scheme>()) {
          if (deferred && !scheme.EvaluateMatrix()) return Status::kNonFinite;
        }
        const Status solved = FactorAndSolve(scheme, key, shifted);
        if (solved != Status::kOk) return solved;
      }
      ++stats_.iterations;
      kept = keep;
      const NewtonCorrection c = scheme.Update();
      stats_.factorizations += c.factorizations;
      if (c.status != Status::kOk) return c.status;
      // (An iterate run off to infinity would pass the increment test by its infinite size.)
      const bool negligible = c.size <= options_.increment_tolerance * c.iterate ||
                              (keep && Predicted(c, r.norm, tolerance));
      if (!shifted && negligible && std::isfinite(c.iterate) && settled(iteration)) {
        if (keep) ++unmeasured_;  // a contraction the driver did not see: Predicted() ages it
        return scheme.Finish();
      }
    }
    return Status::kNotConverged;
  }

  // Whether the scheme can evaluate its residual without its matrix (EvaluateResidual) and the
  // matrix afterwards (EvaluateMatrix): overloads for the test, DefersMatrix<Scheme>() for it.
  template <typename Scheme>
  static auto Defers(Scheme* s, int)
      -> decltype(s->EvaluateResidual(std::declval<NewtonResidual&>()), s->EvaluateMatrix(),
                  std::true_type{});
  template <typename Scheme>
  static std::false_type Defers(Scheme*, long);
  template <typename Scheme>
  static constexpr bool DefersMatrix() {
    return decltype(Defers<Scheme>(nullptr, 0))::value;
  }
  // Whether a kept factor's correction ends the iterations unevaluated: small, and by the
  // contraction the factor last showed, leaving the residual within a tenth of the tolerance.
  // A factor's contraction grows as the state moves away from where it was formed, and an
  // unevaluated end measures none: the estimate doubles with each such end since the last
  // measurement, so that an evaluation comes back to measure it within a few solves. (Taken as
  // it was measured, NewtonDriverTest's creeping load ended at 1.09 times the tolerance.)
  bool Predicted(const NewtonCorrection& c, double norm, double tolerance) const {
    return c.size <= options_.predicted_increment_tolerance * c.iterate &&
           std::ldexp(contraction_, unmeasured_) * norm <= kPredictionMargin * tolerance;
  }

  // Whether the kept factor serves this matrix family and contracted enough last time.
  bool KeptMayServe(double key) const {
    return options_.reuse_contraction > 0.0 && key_ == key &&
           contraction_ <= options_.reuse_contraction;
  }

  // Evaluates at the iterate (the matrix `deferred`), pulling it back into the forces' domain:
  // the prediction to where it was predicted from, a corrected iterate along its last
  // correction. An iterate Newton restarts from after a change of state was evaluated inside
  // already.
  template <typename Scheme>
  static bool EvaluateWithinDomain(Scheme& scheme, int iteration, int settles, bool kept,
                                   bool& deferred, bool& undone, NewtonResidual& r) {
    for (int retreat = 0;; ++retreat) {
      bool inside = false;
      if constexpr (DefersMatrix<Scheme>()) {
        inside = deferred ? scheme.EvaluateResidual(r) : scheme.Evaluate(r);
      } else {
        inside = scheme.Evaluate(r);
      }
      if (inside) return true;
      if (iteration == 0) {
        if (settles > 0 || retreat > 0 || !scheme.BackToStart()) return false;
      } else if (kept && retreat == 0 && scheme.Undo()) {  // the kept factor's correction left
        deferred = false;  // the iterate before, whose fresh factor needs its matrix
        undone = true;
      } else if (retreat == 10 || !scheme.Retreat()) {
        return false;
      }
    }
  }

  // A fresh factor, its mass term raised while the matrix is not definite.
  template <typename Scheme>
  Status FactorAndSolve(Scheme& scheme, double key, bool& shifted) {
    ForgetFactor();
    NewtonFactor f = scheme.Factor(0.0);
    if (f.fresh) ++stats_.factorizations;
    const double mass = scheme.MassTerm();
    for (double shift = mass / 64.0;
         f.status == Status::kNotPositiveDefinite && mass > 0.0 && shift <= kMaxMassShift * mass;
         shift *= 4.0) {
      f = scheme.Factor(shift);
      ++stats_.factorizations;
      shifted = f.status == Status::kOk;
    }
    if (f.status == Status::kOk && f.reusable && !shifted) key_ = key;
    return f.status;
  }

  template <typename Substep, typename Save, typename Revert>
  Status Halves(double from, double to, int depth, Substep& substep, Save& save, Revert& revert) {
    const Status status = substep(from, to, depth);
    if (status == Status::kOk) return status;
    revert();
    if (depth >= options_.max_cuts) return status;
    if (stats_.cuts == 0) save();
    ++stats_.cuts;
    const double mid = 0.5 * (from + to);
    const Status first = Halves(from, mid, depth + 1, substep, save, revert);
    return first == Status::kOk ? Halves(mid, to, depth + 1, substep, save, revert) : first;
  }

  NewtonOptions options_;
  NewtonStats stats_;
  double key_ = kNoFactor;    // the matrix family of the kept factor (NaN: none)
  double contraction_ = 1.0;  // ||R_new|| / ||R|| of the kept factor's last solve
  int unmeasured_ = 0;        // the kept factor's unevaluated ends since (Predicted)
};

}  // namespace cosmems
