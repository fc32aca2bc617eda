#pragma once

#include <Eigen/Core>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/haptics/haptic_physics.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/time/beam_stepper.hpp"

namespace cosmems {

/// The part of HapticPhysics that steps: a model, its probe and the effects its scene declares,
/// stepped by the stepper of the options' path, with the local model of the touched point.
/// HapticStructure (FrameModel, ProbeContact) adds the contact's state and what a frame shows.
template <class Model, class Probe>
class ProbedPhysics : public HapticPhysics {
 public:
  /// `effects` (the scene's forces; nullptr: none) belongs to the caller and must outlive this.
  /// Throws std::invalid_argument on unusable options, std::runtime_error naming the status
  /// when the modal path's modes cannot be found.
  ProbedPhysics(const Model& model, const ProbeOptions& probe, NonlinearForce* effects,
                const HapticPhysicsOptions& options)
      : model_(model), probe_(model, probe), options_(ValidOptions(options)) {
    if (effects) forces_.Add(*effects);
    forces_.Add(probe_);
    const int n = model.FreeDofCount();
    zero_.setZero(n);
    amplitude_.setZero(1);
    const BandCholesky stiffness(model.Stiffness());
    compliance_ = stiffness.info() == Status::kOk
                      ? stiffness.InverseWithinBand()
                      : SymmetricBandMatrix(n, model.Stiffness().bandwidth());
    // The probe and the effects are the forces; the one load pattern stays zero.
    StepperOptions stepper;
    stepper.path = options_.path;
    stepper.time_step = options_.tick_s / options_.Substeps();
    stepper.parameters = GeneralizedAlphaParameters::FromSpectralRadius(options_.rho_inf);
    stepper.modes = options_.modes;
    stepper.newton.residual_tolerance = options_.residual_tolerance;
    if (options_.path == TimePath::kModal) {
      stepper.damping = options_.damping;
    } else {
      stepper.newton.reuse_contraction = options_.reuse_contraction;
      stepper.newton.predicted_increment_tolerance = options_.predicted_increment_tolerance;
    }
    BeamStepperSetup setup = MakeBeamStepper(model, stepper, Eigen::MatrixXd::Zero(n, 1), &forces_);
    if (setup.status != Status::kOk) {
      throw std::runtime_error(std::string("haptic physics: the modal analysis failed: ") +
                               ToString(setup.status));
    }
    stepper_ = std::move(setup.stepper);
    probe_.MoveTo(Eigen::Vector3d(0.0, 1.0, 0.0));  // far above until the hand comes
  }

  Status Advance(const Eigen::Vector3d& probe_m, double source_time_s) override {
    // A position that is no position moves nothing: the tick is refused, the structure kept
    // where it was and the local model invalid, whichever probe would have met it.
    if (!probe_m.allFinite()) {
      status_ = Status::kNonFinite;
      local_.valid = false;
      return status_;
    }
    probe_.MoveTo(probe_m);
    // A factor kept from before the sphere touched lacks its spring, often stiffer than the
    // structure under it: the kept corrections then overshoot past the probe, where a fresh
    // matrix has no spring either (the pressed resonator's first touch: 4 evaluations and 2
    // factorisations where factoring at once takes 2 and 1; doc/speed.md). Letting go needs
    // nothing: the factor with the spring brings the structure back in a correction or two.
    if (probe_.Touches(displacement())) stepper_->ForgetFactor();
    Status status = Status::kOk;
    for (int i = 0; i < options_.Substeps() && status == Status::kOk; ++i) {
      status = stepper_->Step(amplitude_);
    }
    status_ = status;
    UpdateLocalModel(probe_m, source_time_s);
    return status;
  }

  /// Refactors the mass matrix, so it allocates.
  Status Reset() override {
    status_ = stepper_->Initialize(zero_, zero_, amplitude_);
    local_.valid = false;
    return status_;
  }

  const LocalModel& local_model() const override { return local_; }
  double tick_s() const override { return options_.tick_s; }
  int DofCount() const override { return model_.FreeDofCount(); }
  Status status() const { return status_; }
  double time_s() const { return stepper_->time() * model_.units().time; }
  const Model& model() const { return model_; }
  /// Displacement (reduced dofs, internal units).
  const Eigen::VectorXd& displacement() const { return stepper_->displacement(); }
  /// What the last tick's last step cost.
  const NewtonStats& last_stats() const { return stepper_->last_stats(); }
  const Probe& probe() const { return probe_; }

 protected:
  /// The fields of a frame every structure fills: time, probe, its force and the status.
  void FillProbe(HapticFrame& frame) const {
    frame.time_s = time_s();
    frame.probe_m = local_.probe_m;
    frame.probe_force_n = local_.force_n * local_.normal;
    frame.status = status_;
  }

  const Model& model_;

 private:
  static HapticPhysicsOptions ValidOptions(const HapticPhysicsOptions& options) {
    options.Validate();
    return options;
  }

  // The stiffness the probe meets along the face's normal, d(force)/d(depth): the coupling k_c
  // in series with the structure's k_s = 1 / (N^T K^-1 N) at the face's point (the linear
  // structure's; one held by the substrate is stiffer, so the servo loop's extrapolation errs on
  // the soft, passive side), from K^-1's band, formed once: a few multiply-adds a tick where a
  // solve with K took a tenth of the tick. A face that does not move leaves k_c.
  void UpdateLocalModel(const Eigen::Vector3d& probe_m, double source_time_s) {
    const Eigen::VectorXd& d = displacement();
    const double k_c = probe_.stiffness_n_per_m();
    const ProbeTouch touch = probe_.Touch(d);
    const double compliance = probe_.Compliance(touch.face, compliance_) * model_.units().length /
                              model_.units().force;  // m/N
    local_.probe_m = probe_m;
    local_.source_time_s = source_time_s;
    local_.normal = touch.normal;
    local_.stiffness_n_per_m = compliance > 0.0 ? k_c / (1.0 + k_c * compliance) : k_c;
    local_.force_n = touch.force_n;
    local_.clearance_m = touch.depth_m < 0.0 ? -touch.depth_m : 0.0;
    local_.valid = status_ == Status::kOk && std::isfinite(local_.force_n);
  }

  Probe probe_;
  HapticPhysicsOptions options_;
  ForceSum forces_;
  std::unique_ptr<BeamStepper> stepper_;
  SymmetricBandMatrix compliance_;  ///< the band of K^-1 (zero where K is singular)
  Eigen::VectorXd zero_, amplitude_;
  LocalModel local_;
  Status status_ = Status::kOk;
};

}  // namespace cosmems
