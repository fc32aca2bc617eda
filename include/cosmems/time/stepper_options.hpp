#pragma once

#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/newton_options.hpp"

namespace cosmems {

/// How a beam advances in time.
enum class TimePath {
  kNewmarkFamily,  ///< full order, the linear fast path with GeneralizedAlphaParameters
  kModal,          ///< `modes` modes propagated exactly, truncated modes statically
};

/// What a BeamStepper is built from (MakeBeamStepper): the path and its settings.
struct StepperOptions {
  TimePath path = TimePath::kNewmarkFamily;
  double time_step = 0.0;                 ///< s
  GeneralizedAlphaParameters parameters;  ///< for kNewmarkFamily
  int modes = 0;                          ///< for kModal: >= 1
  /// Rayleigh damping fitted to the two lowest modes on the full path, modal ratios on the
  /// modal one.
  DampingModel damping;
  SpdSolverKind solver = SpdSolverKind::kAuto;  ///< the linear full path's factorisation
  NewtonOptions newton;                         ///< the nonlinear paths'
};

}  // namespace cosmems
