#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/analysis/transient_recorder.hpp"
#include "cosmems/analysis/transient_result.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/time/beam_stepper.hpp"
#include "cosmems/time/load_time_function.hpp"

namespace cosmems {

/// A transient run of `model` under `loads` (one spatial pattern times the time function), by
/// the BeamStepper of `options.path` (MakeBeamStepper): the full-order Newmark family or modal
/// propagation. With a nonlinear `force` (stretching, contact, surface pressures) the Newmark
/// family takes its Newton path, the modal path holds the force over each step, and a static
/// start solves the nonlinear statics.
template <int Dim>
TransientResult RunTransient(const BeamModel<Dim>& model, const LoadCase& loads,
                             const TransientOptions& options, NonlinearForce* force = nullptr) {
  options.Validate();
  TransientRecorder recorder(options, model.description().Length());
  TransientResult result;
  const int n = model.FreeDofCount();
  const Eigen::VectorXd pattern = AssembleLoads(model, loads);
  const OutputPoint output = OutputPoint::DeflectionAt(model, options.output_x);

  Eigen::VectorXd d0 = Eigen::VectorXd::Zero(n);
  if (options.start_static && force) {
    const NonlinearStaticSolution deflected = SolveNonlinearStatic(model, *force, loads);
    if (deflected.status != Status::kOk) {
      result.status = deflected.status;
      return result;
    }
    d0 = deflected.displacement;
  } else if (options.start_static) {
    const BandCholesky stiffness(model.Stiffness());
    if (stiffness.info() != Status::kOk) {
      result.status = stiffness.info();
      return result;
    }
    d0 = stiffness.Solve(pattern);
  }
  const BeamStepperSetup setup = MakeBeamStepper(model, options.Stepper(), pattern, force);
  result.status = setup.status;
  if (setup.status != Status::kOk) return result;
  BeamStepper& stepper = *setup.stepper;
  stepper.Watch(output);
  Eigen::VectorXd s = Eigen::VectorXd::Constant(1, options.Amplitude(0));
  result.status = stepper.Initialize(d0, Eigen::VectorXd::Zero(n), s);
  if (result.status != Status::kOk) return result;
  recorder.Run(
      result,
      [&](long i) {
        s[0] = options.Amplitude(i);
        return stepper.Step(s);
      },
      [&] { return stepper.Watched(); });
  recorder.Finish(result);
  return result;
}

}  // namespace cosmems
