#pragma once

#include <stdexcept>

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Convergence of the Newton iterations of a nonlinear step. Both tests are relative, so the
/// same options serve a 100 nm beam and a 5 mm one.
struct NewtonOptions {
  /// ||R|| <= residual_tolerance * (||f|| + ||M (a + c_M v)|| + ||K (d + c_K v)|| + ||r||): the
  /// residual against the size of the terms it balances, the Rayleigh damping C = c_M M + c_K K
  /// counted with the inertia and the elastic force it is proportional to (a static solve's:
  /// ||f|| + ||K d|| + ||r||).
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
  /// A kept factor's correction below predicted_increment_tolerance of the iterate, which the
  /// contraction that factor last showed (doubled at each such end since) predicts to leave the
  /// residual within a tenth of its tolerance, ends the iterations without evaluating the residual
  /// again: the increment test with the contraction as its witness. 0 (the analyses'): every step
  /// ends on an evaluated residual or the increment test. Must lie in [0, 1e-3].
  double predicted_increment_tolerance = 0.0;
  /// A failed step is retried as two half steps, recursively, at most this deep (2^-8 dt).
  int max_cuts = 8;
  /// State changes a force may ask for once Newton has converged (a contact multiplier updated, a
  /// node peeled off: NonlinearForce::Settle), each followed by a fresh set of iterations, in one
  /// step or one load step.
  int max_settles = 200;
};

/// Newton's defaults for rods: NewtonOptions with a residual tolerance of 1e-9 instead of 1e-10.
/// A strain formed from nodal positions carries a round-off floor in the residual, of order
/// EA eps |u| / h: measured 1e-11 to 3e-11 of the reference size for the reference cantilever
/// (50 and 200 elements, PL^2/EI from 0.01 to 2), and the Kirchhoff factor higher in that limit.
/// 1e-10 would sit within a factor 3 of it and cost a haptic re-solve a third iteration (the
/// increment test ends the iterations at the floor either way). A residual of 1e-9 of the loads
/// is a deflection error of order 1e-9 L.
inline NewtonOptions RodNewtonOptions() {
  NewtonOptions options;
  options.residual_tolerance = 1e-9;
  return options;
}

/// Throws std::invalid_argument naming the field and value when a NewtonOptions is not usable.
inline void ValidateNewtonOptions(const NewtonOptions& options) {
  RequirePositive("newton.residual_tolerance", options.residual_tolerance);
  RequirePositive("newton.increment_tolerance", options.increment_tolerance);
  RequireWithin("newton.predicted_increment_tolerance", options.predicted_increment_tolerance, 0.0,
                1e-3);
  RequireWithin("newton.max_iterations", options.max_iterations, 1, 1000);
  RequireWithin("newton.max_cuts", options.max_cuts, 0, 50);
  RequireWithin("newton.max_settles", options.max_settles, 0, 100000);
  if (!(options.reuse_contraction >= 0.0 && options.reuse_contraction < 1.0)) {
    throw std::invalid_argument("newton.reuse_contraction = " +
                                FormatValue(options.reuse_contraction) + ": must lie in [0, 1)");
  }
}

}  // namespace cosmems
