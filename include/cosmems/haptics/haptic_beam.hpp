#pragma once

#include <Eigen/Core>
#include <memory>
#include <stdexcept>
#include <string>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/haptics/haptic_frame.hpp"
#include "cosmems/haptics/local_model.hpp"
#include "cosmems/haptics/probe_contact.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/beam_stepper.hpp"
#include "cosmems/time/stepper_options.hpp"

namespace cosmems {

/// How the physics advances between two servo ticks.
struct HapticPhysicsOptions {
  double tick_s = 1e-3;  ///< simulated time per Advance() (the servo period)
  /// Implicit steps per tick. The reference cantilever's first mode (68.8 kHz) is far above the
  /// servo rate, so the steps do not resolve it whatever their number: the hand feels the
  /// quasi-static beam. Fewer are faster (bench/surface_tick_bench.cpp; the figures are in
  /// doc/surface.md); 2 take every tick of the tests' lay-downs and peels.
  int substeps = 2;
  /// Generalised-alpha's spectral radius: 0 annihilates the unresolved vibrations (the hand
  /// feels the quasi-static beam, as it would the real one) and adds no energy at impacts.
  double rho_inf = 0.0;
  /// The time path (analysis.integrator = "modal" with model.modes): the Newmark family on the
  /// full model, or `modes` modes with the forces held over each step and the truncated modes
  /// answering statically.
  TimePath path = TimePath::kNewmarkFamily;
  int modes = 0;
  /// The modal path's damping, as ratios of the modes (the real beam's quality factor): exact
  /// propagation keeps every mode it does not damp ringing under the hand. The full path leaves
  /// it out (rho_inf removes what the ticks do not resolve).
  DampingModel damping;

  void Validate() const {
    RequirePositive("tick_s", tick_s);
    RequireWithin("substeps", substeps, 1, 10000);
    RequireWithin("rho_inf", rho_inf, 0.0, 1.0);
    if (path == TimePath::kModal) RequireWithin("modes", modes, 1, 10000);
  }
};

/// The beam as the hand touches it: the structure, the effects its scene declares and the probe
/// (ProbeContact), advanced one servo tick at a time. After each tick it holds the LocalModel the
/// servo loop renders and the frame the display shows. Advance() allocates nothing and returns a
/// status; a failed tick leaves the beam where it was and the local model invalid (the safety
/// layer then brings the force to zero).
template <int Dim>
class HapticBeam {
 public:
  /// `effects` (the scene's forces; nullptr: none) and `contact` (the substrate contact among
  /// them, for its state and events; nullptr: none) belong to the caller and must outlive this.
  /// Throws std::invalid_argument on unusable options, std::runtime_error naming the status
  /// when the modal path's modes cannot be found.
  HapticBeam(const BeamModel<Dim>& model, const ProbeOptions& probe, NonlinearForce* effects,
             SubstrateContact<Dim>* contact, const HapticPhysicsOptions& options = {})
      : model_(model), probe_(model, probe), contact_(contact), options_(ValidOptions(options)) {
    if (effects) forces_.Add(*effects);
    forces_.Add(probe_);
    const int n = model.FreeDofCount();
    zero_.setZero(n);
    amplitude_.setZero(1);
    shape_.setZero(n);
    compliance_work_.setZero(n);
    compliance_factor_.Compute(model.Stiffness());
    // The probe and the effects are the forces; the one load pattern stays zero.
    StepperOptions stepper;
    stepper.path = options_.path;
    stepper.time_step = options_.tick_s / options_.substeps;
    stepper.parameters = GeneralizedAlphaParameters::FromSpectralRadius(options_.rho_inf);
    stepper.modes = options_.modes;
    if (options_.path == TimePath::kModal) stepper.damping = options_.damping;
    BeamStepperSetup setup = MakeBeamStepper(model, stepper, Eigen::MatrixXd::Zero(n, 1), &forces_);
    if (setup.status != Status::kOk) {
      throw std::runtime_error(std::string("haptic physics: the modal analysis failed: ") +
                               ToString(setup.status));
    }
    stepper_ = std::move(setup.stepper);
    probe_.MoveTo(Eigen::Vector3d(0.0, 1.0, 0.0));  // far above until the hand comes
    Reset();
  }

  /// One tick: the probe moves to `probe_m` [m, beam axes] (where the hand put it at device time
  /// `source_time_s`) and the beam advances by tick_s.
  Status Advance(const Eigen::Vector3d& probe_m, double source_time_s) {
    probe_.MoveTo(probe_m);
    Status status = Status::kOk;
    for (int i = 0; i < options_.substeps && status == Status::kOk; ++i) {
      status = stepper_->Step(amplitude_);
    }
    status_ = status;
    UpdateLocalModel(probe_m, source_time_s);
    return status;
  }

  /// The paper's "Reset Failure": the undeformed beam at rest, nothing stuck (events are kept).
  /// Refactors the mass matrix, so it allocates: call it outside the servo thread when threads
  /// are split (HapticLoop does).
  Status Reset() {
    if (contact_) contact_->Reset();
    status_ = stepper_->Initialize(zero_, zero_, amplitude_);
    local_.valid = false;
    return status_;
  }

  const LocalModel& local_model() const { return local_; }
  Status status() const { return status_; }
  double time_s() const { return stepper_->time() * model_.units().time; }
  /// Simulated time one Advance() covers [s].
  double tick_s() const { return options_.tick_s; }
  const BeamModel<Dim>& model() const { return model_; }
  /// Displacement (reduced dofs, internal units).
  const Eigen::VectorXd& displacement() const { return stepper_->displacement(); }
  /// What the last tick's last step cost.
  const NewtonStats& last_stats() const { return stepper_->last_stats(); }
  const ProbeContact<Dim>& probe() const { return probe_; }
  const SubstrateContact<Dim>* contact() const { return contact_; }

  /// A frame sized for this beam (allocates: call once).
  HapticFrame MakeFrame() const {
    HapticFrame frame;
    const int nodes = static_cast<int>(model_.NodeX().size());
    frame.node_x_m.resize(nodes);
    for (int k = 0; k < nodes; ++k) frame.node_x_m[k] = model_.NodeX()[k] * model_.units().length;
    frame.deflection_m.setZero(nodes);
    frame.rotation_rad.setZero(nodes);
    Fill(frame);
    return frame;
  }

  /// Copies the current state into a frame from MakeFrame(); allocates nothing.
  void Fill(HapticFrame& frame) const {
    const Eigen::VectorXd& d = displacement();
    frame.time_s = time_s();
    frame.probe_m = local_.probe_m;
    frame.probe_force_n = local_.force_n * local_.normal;
    for (int k = 0; k < frame.deflection_m.size(); ++k) {
      const int dof = model_.dofs().Reduced(k, NodalDof::kUy);
      frame.deflection_m[k] = dof >= 0 ? d[dof] * model_.units().length : 0.0;
      const int rotation = model_.dofs().Reduced(k, NodalDof::kRz);
      frame.rotation_rad[k] = rotation >= 0 ? d[rotation] : 0.0;  // radians in every unit system
    }
    if (contact_) {
      frame.contact = contact_->Summary();
      frame.events = contact_->events();
    }
    frame.status = status_;
  }

 private:
  static HapticPhysicsOptions ValidOptions(const HapticPhysicsOptions& options) {
    options.Validate();
    return options;
  }

  // The stiffness the probe meets along the face's normal, d(force)/d(depth): the coupling k_c
  // in series with the beam's k_b = 1 / (N^T K^-1 N) at the face's point (the linear beam's; a
  // beam held by the substrate is stiffer, so the servo loop's extrapolation errs on the soft,
  // passive side). A face that does not move leaves k_c.
  void UpdateLocalModel(const Eigen::Vector3d& probe_m, double source_time_s) {
    const Eigen::VectorXd& d = displacement();
    const double k_c = probe_.stiffness_n_per_m();
    const ProbeTouch touch = probe_.Touch(d);
    probe_.ShapeVector(touch.face, shape_);
    compliance_work_ = shape_;
    compliance_factor_.SolveInPlace(compliance_work_);
    const double compliance =
        shape_.dot(compliance_work_) * model_.units().length / model_.units().force;  // m/N
    local_.probe_m = probe_m;
    local_.source_time_s = source_time_s;
    local_.normal = touch.normal;
    local_.stiffness_n_per_m = compliance > 0.0 ? k_c / (1.0 + k_c * compliance) : k_c;
    local_.force_n = touch.force_n;
    local_.clearance_m = touch.depth_m < 0.0 ? -touch.depth_m : 0.0;
    local_.valid = status_ == Status::kOk && std::isfinite(local_.force_n);
  }

  const BeamModel<Dim>& model_;
  ProbeContact<Dim> probe_;
  SubstrateContact<Dim>* contact_;
  HapticPhysicsOptions options_;
  ForceSum forces_;
  std::unique_ptr<BeamStepper> stepper_;
  BandCholesky compliance_factor_;
  Eigen::VectorXd zero_, amplitude_, shape_, compliance_work_;
  LocalModel local_;
  Status status_ = Status::kOk;
};

}  // namespace cosmems
