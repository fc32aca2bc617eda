#pragma once

#include <Eigen/Core>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/haptics/probe_contact.hpp"
#include "cosmems/haptics/probed_physics.hpp"
#include "cosmems/surface/substrate_contact.hpp"

namespace cosmems {

/// The beam as the hand touches it: the beam, the effects its scene declares and the probe
/// (ProbeContact), advanced one servo tick at a time (ProbedPhysics); its frames carry the
/// beam's deflection and the substrate contact's state.
template <int Dim>
class HapticBeam final : public ProbedPhysics<BeamModel<Dim>, ProbeContact<Dim>> {
  using Base = ProbedPhysics<BeamModel<Dim>, ProbeContact<Dim>>;

 public:
  /// `effects` (the scene's forces; nullptr: none) and `contact` (the substrate contact among
  /// them, for its state and events; nullptr: none) belong to the caller and must outlive this.
  /// Throws as ProbedPhysics does.
  HapticBeam(const BeamModel<Dim>& model, const ProbeOptions& probe, NonlinearForce* effects,
             SubstrateContact<Dim>* contact, const HapticPhysicsOptions& options = {})
      : Base(model, probe, effects, options), contact_(contact) {
    Reset();
  }

  /// The beam at rest with nothing stuck.
  Status Reset() override {
    if (contact_) contact_->Reset();
    return Base::Reset();
  }

  const SubstrateContact<Dim>* contact() const { return contact_; }

  HapticFrame MakeFrame() const override {
    HapticFrame frame;
    const int nodes = static_cast<int>(model_.NodeX().size());
    frame.node_x_m.resize(nodes);
    for (int k = 0; k < nodes; ++k) frame.node_x_m[k] = model_.NodeX()[k] * model_.units().length;
    frame.deflection_m.setZero(nodes);
    frame.rotation_rad.setZero(nodes);
    Fill(frame);
    return frame;
  }

  void Fill(HapticFrame& frame) const override {
    this->FillProbe(frame);
    const Eigen::VectorXd& d = this->displacement();
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
  }

 private:
  using Base::model_;
  SubstrateContact<Dim>* contact_;
};

}  // namespace cosmems
