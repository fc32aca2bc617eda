#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosmems/core/status.hpp"

namespace cosmems {

/// Options of FindFold.
struct FoldOptions {
  double first_step = 0.02;  ///< of the travel parameter s (a fraction of the gap)
  double max_travel = 0.99;  ///< no fold short of this: Status::kNotConverged
  /// The fold is located when the load's slope d lambda / ds has fallen below this fraction of
  /// its value at s = 0; the quadratic model then leaves an error of order its cube in lambda.
  double slope_tolerance = 1e-3;
  int max_solves = 400;
  /// A bound on the load: a path that passes it before its fold ends there with
  /// Status::kNotConverged (no fold below the bound).
  double max_load = std::numeric_limits<double>::infinity();
  /// Where the path loses stability while its load still rises (a bifurcation), the bracket
  /// between the last stable travel and the first unstable one is narrowed to this width; the
  /// load there is then known to its slope times half of it.
  double travel_tolerance = 1e-7;
};

/// How an equilibrium path ends its stable part.
enum class Instability {
  kLimitPoint,   ///< the load reaches its largest value (the fold): the classic pull-in
  kBifurcation,  ///< the path's matrix turns singular while the load still rises: another mode
                 ///< (a symmetric device's tilt, say) takes over
};

constexpr const char* ToString(Instability instability) {
  return instability == Instability::kLimitPoint ? "limit_point" : "bifurcation";
}

/// The end of the stable part of an equilibrium path: where the load factor is largest, or where
/// a bifurcation cuts the path short.
struct FoldPoint {
  Status status = Status::kOk;
  Instability instability = Instability::kLimitPoint;
  double travel = 0.0;              ///< s at the fold
  double load = 0.0;                ///< lambda at the fold
  double last_stable_travel = 0.0;  ///< the last solved state before it
  int solves = 0;
};

/// Finds the fold of a path lambda(s) traced by displacement control: `path.Solve(s, lambda,
/// slope)` finds the equilibrium at travel s (from the last accepted one) and returns its load
/// factor and d lambda / ds, or a status when there is no stable equilibrium there
/// (Status::kNotPositiveDefinite: past the fold, or past a bifurcation) or Newton failed to find
/// one; `path.Accept()` makes the last solved state the start of the next solve.
///
/// Steps grow while the slope holds. Near the fold the slope falls linearly in s (lambda is
/// quadratic there), so the last two slopes extrapolate to the fold's travel, and the next step
/// goes half way there: the solves approach the fold from the stable side, where the path's
/// matrix stays positive definite, and never rely on a failed solve to find it (a failure only
/// shortens the step). The load at the fold is the quadratic model's, lambda + slope (s* - s)/2.
///
/// The path's matrix can also turn singular where the load still rises: its null vector is then
/// orthogonal to the load (a symmetric structure's antisymmetric mode), the controlled travel
/// passes smoothly, and the states beyond are unstable under load control. A solve found unstable
/// bounds the stable part from above; steps halve toward that bound until the bracket is narrower
/// than options.travel_tolerance, and a slope still above the slope tolerance there marks a
/// bifurcation, whose load is lambda + slope times half the bracket.
template <typename Path>
FoldPoint FindFold(Path& path, const FoldOptions& options = {}) {
  FoldPoint out;
  double s = 0.0, lambda = 0.0, slope = 0.0;
  out.status = path.Solve(0.0, lambda, slope);
  ++out.solves;
  if (out.status != Status::kOk) return out;
  path.Accept();
  const double first_slope = slope;
  double previous_s = 0.0, previous_slope = slope;
  double step = options.first_step;
  const double infinity = std::numeric_limits<double>::infinity();
  double fold = infinity;   // the travel the last two slopes extrapolate to
  double upper = infinity;  // the smallest travel found past the fold (or too far to solve)
  while (out.solves < options.max_solves) {
    if (slope <= options.slope_tolerance * first_slope || fold - s <= 1e-12 ||
        upper - s <= options.travel_tolerance) {
      break;
    }
    const double target =
        std::min({s + step, 0.5 * (s + fold), 0.5 * (s + upper), options.max_travel});
    if (target <= s) {
      out.status = Status::kNotConverged;  // no fold before max_travel
      return out;
    }
    double trial_lambda = 0.0, trial_slope = 0.0;
    const Status status = path.Solve(target, trial_lambda, trial_slope);
    ++out.solves;
    if (status != Status::kOk || !(trial_slope > 0.0)) {
      // Unstable or past the fold: an upper bound. A Newton failure only shortens the step.
      if (status == Status::kNotPositiveDefinite || status == Status::kOk) {
        upper = std::min(upper, target);
      }
      step = 0.5 * (target - s);
      continue;
    }
    path.Accept();
    if (trial_lambda > options.max_load) {
      out.status = Status::kNotConverged;
      out.last_stable_travel = out.travel = target;
      out.load = trial_lambda;
      return out;
    }
    previous_s = s;
    previous_slope = slope;
    s = target;
    lambda = trial_lambda;
    slope = trial_slope;
    step *= 2.0;
    fold =
        previous_slope > slope ? s + slope * (s - previous_s) / (previous_slope - slope) : infinity;
  }
  if (out.solves >= options.max_solves) out.status = Status::kNotConverged;
  if (slope > options.slope_tolerance * first_slope && upper - s <= options.travel_tolerance) {
    out.instability = Instability::kBifurcation;
    out.travel = 0.5 * (s + upper);
    out.load = lambda + slope * (out.travel - s);
    out.last_stable_travel = s;
    return out;
  }
  const double end = std::min(std::isfinite(fold) ? fold : s, upper);
  out.travel = end;
  out.load = lambda + 0.5 * slope * (end - s);
  out.last_stable_travel = s;
  return out;
}

}  // namespace cosmems
