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
  /// A failed step is retried as two half steps, recursively, at most this deep (2^-8 dt).
  int max_cuts = 8;
};

}  // namespace cosmems
