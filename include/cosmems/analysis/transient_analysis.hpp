#pragma once

#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/output_point.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/analysis/transient_recorder.hpp"
#include "cosmems/analysis/transient_result.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/load_time_function.hpp"
#include "cosmems/time/modal_model.hpp"
#include "cosmems/time/modal_propagator.hpp"
#include "cosmems/time/nonlinear_modal_integrator.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"

namespace cosmems {

/// A transient run of `model` under `loads` (one spatial pattern times the time function), by
/// the full-order Newmark family or by exact modal propagation. With a nonlinear `force`
/// (stretching, contact, surface pressures) the Newmark family takes its Newton path, the modal
/// path holds the force over each step (NonlinearModalIntegrator), and a static start solves the
/// nonlinear statics.
template <int Dim>
TransientResult RunTransient(const BeamModel<Dim>& model, const LoadCase& loads,
                             const TransientOptions& options, NonlinearForce* force = nullptr) {
  options.Validate();
  TransientRecorder recorder(options, model.description().Length());
  TransientResult result;
  const UnitSystem& units = model.units();
  const int n = model.FreeDofCount();
  const double dt = options.time_step / units.time;
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
  if (options.path == TimePath::kModal) {
    ModalOptions modal_options;
    modal_options.count = options.modes;
    const ModalResult modes = SolveModal(model, modal_options);
    if (modes.status != Status::kOk) {
      result.status = modes.status;
      return result;
    }
    const ModalModel modal = MakeModalModel(model, modes, options.damping);
    Eigen::VectorXd s = Eigen::VectorXd::Constant(1, options.Amplitude(0));
    if (force) {
      NonlinearModalIntegrator integrator(model, modal, pattern, *force, dt);
      result.status = integrator.Initialize(d0, Eigen::VectorXd::Zero(n), s);
      if (result.status != Status::kOk) return result;
      recorder.Run(
          result,
          [&](long i) {
            s[0] = options.Amplitude(i);
            return integrator.Step(s);
          },
          [&] { return output.Evaluate(integrator.displacement()); });
      recorder.Finish(result);
      return result;
    }
    const Eigen::MatrixXd residual = modal.ResidualFlexibility(model, pattern);
    ModalPropagator propagator(modal.coordinates, modal.shapes, pattern, residual, dt);
    propagator.Initialize(modal.Project(model, (d0 - residual * s).eval()),
                          Eigen::VectorXd::Zero(modal.shapes.cols()), s);
    const Eigen::RowVectorXd output_shapes = output.Evaluate(modal.shapes);
    const double output_static = output.Evaluate(residual.col(0).eval());
    recorder.Run(
        result,
        [&](long i) {
          s[0] = options.Amplitude(i);
          return propagator.Step(s);
        },
        [&] { return output_shapes.dot(propagator.modal_displacement()) + output_static * s[0]; });
  } else {
    RayleighDamping damping;
    if (options.damping.kind != DampingModel::Kind::kNone) {
      ModalOptions two;
      two.count = 2;
      const ModalResult lowest = SolveModal(model, two);
      const double w1 = 2.0 * kPi * lowest.modes.at(0).frequency_hz;
      const double w2 =
          lowest.modes.size() > 1 ? 2.0 * kPi * lowest.modes[1].frequency_hz : 3.0 * w1;
      damping = options.damping.ForFullModel(w1, w2, units);
    }
    // Returns false when the integrator could not start (the status says why).
    auto march = [&](auto& integrator) {
      Eigen::VectorXd f = pattern * options.Amplitude(0);
      result.status = integrator.Initialize(d0, Eigen::VectorXd::Zero(n), f);
      if (result.status != Status::kOk) return false;
      recorder.Run(
          result,
          [&](long i) {
            f = pattern * options.Amplitude(i);
            return integrator.Step(f);
          },
          [&] { return output.Evaluate(integrator.displacement()); });
      return true;
    };
    bool started = false;
    if (force) {
      NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), damping, *force,
                                            options.parameters, dt);
      started = march(integrator);
    } else {
      LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), damping,
                                         options.parameters, dt, options.solver);
      started = march(integrator);
    }
    if (!started) return result;
  }
  recorder.Finish(result);
  return result;
}

}  // namespace cosmems
