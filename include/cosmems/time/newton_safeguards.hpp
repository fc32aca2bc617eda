#pragma once

#include <Eigen/Core>

#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"

namespace cosmems {

// What the Newton paths of the time integrators do where a step's iterations go wrong.

/// Advances the fraction [from, to] of a time step by `substep(from, to, depth)`, depth being how
/// many times the step was halved to get there, and retries a failed part as two halves,
/// recursively up to `max_cuts` deep. After each failure the force returns to its last committed
/// state (Revert); before the first cut `save()` keeps the state at the step's start, which a
/// failed sub-step leaves alone, for the caller to return to if even the cuts fail. `cuts` counts
/// the cuts. Allocates nothing.
template <typename Substep, typename Save>
Status AdvanceInHalves(double from, double to, int depth, int max_cuts, NonlinearForce& force,
                       int& cuts, Substep& substep, Save& save) {
  const Status status = substep(from, to, depth);
  if (status == Status::kOk) return status;
  force.Revert();
  if (depth >= max_cuts) return status;
  if (cuts == 0) save();
  ++cuts;
  const double mid = 0.5 * (from + to);
  const Status first = AdvanceInHalves(from, mid, depth + 1, max_cuts, force, cuts, substep, save);
  return first == Status::kOk
             ? AdvanceInHalves(mid, to, depth + 1, max_cuts, force, cuts, substep, save)
             : first;
}

/// Evaluates `force` at `d` into `r` and `tangent`, both cleared first. An iterate outside the
/// force's domain (a gap closed under a 1/gap^n pressure) is pulled back along the increment that
/// brought it there, which `increment` still holds (d = previous - increment), halving it up to
/// 10 times and calling `moved()` after each retreat; the first iterate of a step (`first`), the
/// predictor, has no increment to retreat along. False if no retreat helps. Allocates nothing.
template <typename Moved>
bool EvaluateWithinDomain(NonlinearForce& force, bool first, Eigen::VectorXd& d,
                          Eigen::VectorXd& increment, Eigen::VectorXd& r, ForceTangent& tangent,
                          Moved&& moved) {
  for (int retreat = 0;; ++retreat) {
    r.setZero();
    tangent.Clear();
    if (force.Evaluate(d, r, tangent)) return true;
    if (first || retreat == 10) return false;
    increment *= 0.5;
    d += increment;
    moved();
  }
}

}  // namespace cosmems
