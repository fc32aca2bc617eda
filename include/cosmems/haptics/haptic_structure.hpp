#pragma once

#include "cosmems/haptics/probe_contact.hpp"
#include "cosmems/haptics/probed_physics.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"

namespace cosmems {

/// Any structure (a FrameModel: members, bodies, anchors) as the hand touches it: the effects
/// its scene declares and the probe on every member's and body's faces (ProbeContact),
/// advanced one servo tick at a time (ProbedPhysics). On the modal path (many elements) a tick
/// costs the modes', not the band's. Its frames carry every carrier's motion and the substrate
/// contact's state.
class HapticStructure final : public ProbedPhysics<FrameModel, ProbeContact> {
 public:
  /// `effects` (the scene's forces; nullptr: none) and `contact` (the substrate contact among
  /// them, for its state and events; nullptr: none) belong to the caller and must outlive this.
  /// Throws as ProbedPhysics does.
  HapticStructure(const FrameModel& model, const ProbeOptions& probe, NonlinearForce* effects,
                  FrameSubstrateContact* contact, const HapticPhysicsOptions& options = {})
      : ProbedPhysics(model, probe, effects, options), contact_(contact) {
    Reset();
  }

  /// The structure at rest, the contact free.
  Status Reset() override {
    if (contact_) contact_->Reset();
    return ProbedPhysics::Reset();
  }

  const FrameSubstrateContact* contact() const { return contact_; }

  HapticFrame MakeFrame() const override {
    HapticFrame frame;
    frame.carrier_motion_m.setZero(6, static_cast<Eigen::Index>(model_.mesh().carriers.size()));
    Fill(frame);
    return frame;
  }
  void Fill(HapticFrame& frame) const override {
    FillProbe(frame);
    const double length_m = model_.units().length;
    for (Eigen::Index c = 0; c < frame.carrier_motion_m.cols(); ++c) {
      const FrameModel::Motion q = model_.CarrierMotion(displacement(), static_cast<int>(c));
      frame.carrier_motion_m.col(c) << length_m * q.head<3>(), q.tail<3>();
    }
    if (contact_) {
      frame.contact = contact_->Summary();
      frame.events = contact_->events();
    }
  }

 private:
  FrameSubstrateContact* contact_;
};

}  // namespace cosmems
