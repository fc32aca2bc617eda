#pragma once

// The paper's scene for the example programs: the silicon reference cantilever (200 x 20 x 2 um,
// 20 planar elements, built as its one-member netlist) 2 um above the substrate with contact,
// stiction (0.02 J/m^2) and the Casimir force, a probe tied to the stylus by a 21 N/m coupling (25
// times the tip's stiffness), and the hand scaled so that 1 um of the beam is 5 mm of hand and the
// coupling is felt at half the device's renderable stiffness. The stylus starts over the tip.
#include <memory>

#include "cosmems/beam/force_sum.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/structure/straight_beam.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "cosmems/surface/gap_pressures.hpp"

namespace cosmems::example {

class TouchableCantilever {
 public:
  static constexpr double kLength = 200e-6, kThickness = 2e-6, kGap = 2e-6;

  TouchableCantilever(const DeviceSpecs& specs, PhysicsThread physics)
      : model_(StraightBeam(Design())),
        contact_(model_, Contact()),
        casimir_(model_, CasimirPressure{}, Under()) {
    forces_.Add(contact_);
    forces_.Add(casimir_);
    const double k_tip = 3.0 * 169e9 * (20e-6 * 8e-18 / 12.0) / (kLength * kLength * kLength);
    ProbeOptions probe{kThickness, 25.0 * k_tip};
    HapticPhysicsOptions physics_options;
    physics_options.tick_s = 1.0 / specs.nominal_rate_hz;  // one physics tick a servo tick
    beam_ = std::make_unique<HapticStructure>(model_, probe, &forces_, &contact_, physics_options);
    HapticLoopOptions options;
    options.physics = physics;
    options.scaling.position_scale = 5000.0;
    options.scaling.force_scale =
        0.5 * specs.max_stiffness_n_per_m * options.scaling.position_scale / probe.stiffness;
    // The device's centre is the probe one gap above the tip's upper face.
    options.scaling.device_origin_m =
        -options.scaling.position_scale *
        Eigen::Vector3d(kLength, 0.5 * kThickness + probe.radius + kGap, 0.0);
    loop_ = std::make_unique<HapticLoop>(*beam_, options);
  }

  HapticLoop& loop() { return *loop_; }

  /// The tip's deflection u_y [m] in a frame (the tip is the netlist's node 1).
  double TipDeflection(const HapticFrame& frame) const {
    return frame.carrier_motion_m(1, model_.mesh().nodes[1].carrier);
  }

 private:
  static StraightBeamDesign Design() {
    StraightBeamDesign d;
    d.length = kLength;
    d.material = Material{169e9, 2330.0, 0.22};
    d.section = RectangularSection{20e-6, kThickness};
    d.elements = 20;
    d.series_order = 0;  // Hermite elements
    d.planar = true;
    return d;
  }
  static ContactOptions Contact() {
    ContactOptions c;
    c.gap = kGap;
    c.separation = 2e-8;  // the asperities of a rough surface
    c.stiction = true;
    c.adhesion_energy = 0.02;
    return c;
  }
  // The Casimir pressure held at the asperities' height, where the contact holds the beam.
  static FrameGapOptions Under() {
    FrameGapOptions under{kGap};
    under.separation = Contact().separation;
    return under;
  }

  FrameModel model_;
  FrameSubstrateContact contact_;
  FrameGapForce<CasimirPressure> casimir_;
  ForceSum forces_;
  std::unique_ptr<HapticStructure> beam_;
  std::unique_ptr<HapticLoop> loop_;
};

}  // namespace cosmems::example
