#pragma once

#include <Eigen/Core>
#include <memory>

#include "cosmems/analysis/frame_modal_analysis.hpp"  // SolveModal of a FrameModel
#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/constants.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/time/beam_stepper.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/modal_stepper.hpp"
#include "cosmems/time/newmark_stepper.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "cosmems/time/rayleigh_damping.hpp"
#include "cosmems/time/stepper_options.hpp"

namespace cosmems {

/// A stepper made by MakeBeamStepper, or the status of the set-up that failed (a modal solve).
struct BeamStepperSetup {
  Status status = Status::kOk;
  std::unique_ptr<BeamStepper> stepper;
};

/// The BeamStepper of `options.path` for `model` (a BeamModel or a FrameModel: their reduced
/// matrices, and SolveModal of either) under the load patterns `patterns` (n x m), with
/// the nonlinear `force` (nullptr: none; it must outlive the stepper):
/// - the Newmark family: LinearNewmarkIntegrator without a force (factored once),
///   NonlinearNewmarkIntegrator (Newton) with one; a damping model becomes Rayleigh damping
///   fitted to the two lowest modes;
/// - modal: the `modes` lowest modes (MakeModalModel, their damping as ratios), propagated
///   exactly (ModalStepper) or with the force held over each step (NonlinearModalStepper).
/// Allocates; throws std::invalid_argument on unusable options.
template <class Model>
BeamStepperSetup MakeBeamStepper(const Model& model, const StepperOptions& options,
                                 const Eigen::MatrixXd& patterns, NonlinearForce* force) {
  const double dt = options.time_step / model.units().time;
  BeamStepperSetup out;
  if (options.path == TimePath::kModal) {
    ModalOptions modal_options;
    modal_options.count = options.modes;
    const ModalResult modes = SolveModal(model, modal_options);
    out.status = modes.status;
    if (modes.status != Status::kOk) return out;
    const ModalModel modal = MakeModalModel(model, modes, options.damping);
    if (force) {
      out.stepper = std::make_unique<NonlinearModalStepper>(model, modal, patterns, *force, dt,
                                                            options.newton);
    } else {
      out.stepper = std::make_unique<ModalStepper>(modal, patterns, modal.Fit(model),
                                                   modal.ResidualFlexibility(model, patterns), dt);
    }
    return out;
  }
  RayleighDamping damping;
  if (options.damping.kind != DampingModel::Kind::kNone) {
    ModalOptions two;
    two.count = 2;
    const ModalResult lowest = SolveModal(model, two);
    out.status = lowest.status;
    if (lowest.status != Status::kOk) return out;
    const double w1 = 2.0 * kPi * lowest.modes.at(0).frequency_hz;
    const double w2 = lowest.modes.size() > 1 ? 2.0 * kPi * lowest.modes[1].frequency_hz : 3.0 * w1;
    damping = options.damping.ForFullModel(w1, w2, model.units());
  }
  if (force) {
    out.stepper = std::make_unique<NewmarkStepper<NonlinearNewmarkIntegrator>>(
        patterns, model.Mass(0), model.Stiffness(), damping, *force, options.parameters, dt,
        options.newton);
  } else {
    out.stepper = std::make_unique<NewmarkStepper<LinearNewmarkIntegrator>>(
        patterns, model.Mass(0), model.Stiffness(), damping, options.parameters, dt,
        options.solver);
  }
  return out;
}

}  // namespace cosmems
