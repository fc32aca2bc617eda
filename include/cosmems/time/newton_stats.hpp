#pragma once

namespace cosmems {

/// What a Newton solve, a time step or a load ramp cost, counted by NewtonDriver. Every
/// integrator and nonlinear solver reports this one struct for its last call.
struct NewtonStats {
  int iterations = 0;      ///< Newton corrections (linear solves)
  int evaluations = 0;     ///< residual evaluations (a solve that converges on its residual
                           ///< evaluates once more than it corrects)
  int factorizations = 0;  ///< factorisations of the Newton matrix, shifted ones included
  int cuts = 0;            ///< halvings of a time step or a load step
  int failures = 0;        ///< Newton solves given up (each followed by a cut, or the last one)

  NewtonStats& operator+=(const NewtonStats& o) {
    iterations += o.iterations;
    evaluations += o.evaluations;
    factorizations += o.factorizations;
    cuts += o.cuts;
    failures += o.failures;
    return *this;
  }
};

}  // namespace cosmems
