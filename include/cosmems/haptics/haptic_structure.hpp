#pragma once

#include "cosmems/haptics/frame_probe_contact.hpp"
#include "cosmems/haptics/probed_physics.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// Any structure (a FrameModel: members, bodies, anchors) as the hand touches it: the effects
/// its scene declares and the probe on every member's and body's faces (FrameProbeContact),
/// advanced one servo tick at a time (ProbedPhysics). On the modal path (many elements) a tick
/// costs the modes', not the band's.
class HapticStructure final : public ProbedPhysics<FrameModel, FrameProbeContact> {
 public:
  /// `effects` (the scene's forces; nullptr: none) belongs to the caller and must outlive this.
  /// Throws as ProbedPhysics does.
  HapticStructure(const FrameModel& model, const ProbeOptions& probe, NonlinearForce* effects,
                  const HapticPhysicsOptions& options = {})
      : ProbedPhysics(model, probe, effects, options) {
    Reset();
  }

  HapticFrame MakeFrame() const override {
    HapticFrame frame;
    Fill(frame);
    return frame;
  }
  void Fill(HapticFrame& frame) const override { FillProbe(frame); }
};

}  // namespace cosmems
