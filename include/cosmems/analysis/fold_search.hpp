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
};

/// The fold of an equilibrium path: where the load factor is largest.
struct FoldPoint {
  Status status = Status::kOk;
  double travel = 0.0;              ///< s at the fold
  double load = 0.0;                ///< lambda at the fold
  double last_stable_travel = 0.0;  ///< the last solved state before it
  int solves = 0;
};

/// Finds the fold of a path lambda(s) traced by displacement control: `path.Solve(s, lambda,
/// slope)` finds the equilibrium at travel s (from the last accepted one) and returns its load
/// factor and d lambda / ds, or a status when there is no stable equilibrium there (a
/// factorisation that is not positive definite: past the fold); `path.Accept()` makes the last
/// solved state the start of the next solve.
///
/// Steps grow while the slope holds. Near the fold the slope falls linearly in s (lambda is
/// quadratic there), so the last two slopes extrapolate to the fold's travel, and the next step
/// goes half way there: the solves approach the fold from the stable side, where the path's
/// matrix stays positive definite, and never rely on a failed solve to find it (a failure only
/// shortens the step). The load at the fold is the quadratic model's, lambda + slope (s* - s)/2.
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
    if (slope <= options.slope_tolerance * first_slope || fold - s <= 1e-12) break;
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
      upper = std::min(upper, target);  // beyond the fold, or too far for Newton
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
  const double end = std::min(std::isfinite(fold) ? fold : s, upper);
  out.travel = end;
  out.load = lambda + 0.5 * slope * (end - s);
  out.last_stable_travel = s;
  return out;
}

}  // namespace cosmems
