#pragma once

namespace cosmems {

/// Convergence of the Newton iterations of a nonlinear step. Both tests are relative, so the
/// same options serve a 100 nm beam and a 5 mm one.
struct NewtonOptions {
  /// ||R|| <= residual_tolerance * (||f|| + ||M a|| + ||C v|| + ||K d|| + ||r||): the residual
  /// against the size of the terms it balances.
  double residual_tolerance = 1e-10;
  /// ||delta d|| <= increment_tolerance * ||d||: the last correction changed nothing that matters.
  double increment_tolerance = 1e-12;
  int max_iterations = 25;
  /// The nonlinear Newmark step keeps the band part of its tangent's factorisation, from one
  /// iteration and one step to the next, while its last solve cut the residual at least this
  /// much (||R_new|| <= reuse_contraction ||R||) and, past a step's first iteration, another such
  /// cut would end the step; otherwise it refactors. The residual is exact either way, so the
  /// answer meets the same tolerances, only the path to it is cheaper. 0 refactors at every
  /// iteration (plain Newton); must lie in [0, 1). Values from 1e-3 to 0.5 measured alike.
  double reuse_contraction = 1e-3;
  /// A failed step is retried as two half steps, recursively, at most this deep (2^-8 dt).
  int max_cuts = 8;
  /// State changes a force may ask for once Newton has converged (a contact multiplier updated, a
  /// node peeled off: NonlinearForce::Settle), each followed by a fresh set of iterations, in one
  /// step or one load step.
  int max_settles = 200;

  /// Converged at the floor of rounding: a residual that kept over half its size through the
  /// last iteration and lies within `round_off()`, the rounding error of the products that form
  /// it, below which no iteration can take it. A fine mesh stops there above residual_tolerance:
  /// its K d is a small difference of large products (SymmetricBandMatrix::ProductRoundOff).
  /// `round_off` is called only for a stalled residual, so converging iterations never pay for it.
  template <typename RoundOff>
  static bool StalledAtRoundOff(double norm, double previous_norm, RoundOff&& round_off) {
    return norm >= 0.5 * previous_norm && norm <= round_off();
  }
};

}  // namespace cosmems
