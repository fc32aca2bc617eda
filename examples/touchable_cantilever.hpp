#pragma once

// The paper's scene for the example programs: the silicon reference cantilever (200 x 20 x 2 um,
// 20 planar elements) 2 um above the substrate with contact, stiction (0.02 J/m^2) and the
// Casimir force, a probe tied to the stylus by a 21 N/m coupling (25 times the tip's
// stiffness), and the hand scaled so that 1 um of the beam is 5 mm of hand and the coupling is
// felt at half the device's renderable stiffness. The stylus starts over the tip.
#include <memory>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/force_tuple.hpp"
#include "cosmems/haptics/haptic_beam.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/surface/gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/surface/substrate_contact.hpp"

namespace cosmems::example {

class TouchableCantilever {
 public:
  static constexpr double kLength = 200e-6, kThickness = 2e-6, kGap = 2e-6;

  TouchableCantilever(const DeviceSpecs& specs, PhysicsThread physics)
      : model_(MakeStructure(StructureKind::kCantilever, kLength, Material{169e9, 2330.0, 0.22},
                             RectangularSection{20e-6, kThickness}, 20, 0)),
        forces_(SubstrateContact<2>(model_, Contact()),
                GapForce<2, CasimirPressure>(
                    model_, CasimirPressure{},
                    GapSpan{kGap, 0.0, kLength}.WithSeparation(Contact().separation))) {
    const double k_tip = 3.0 * 169e9 * (20e-6 * 8e-18 / 12.0) / (kLength * kLength * kLength);
    ProbeOptions probe{kThickness, 25.0 * k_tip};
    HapticPhysicsOptions physics_options;
    physics_options.tick_s = 1.0 / specs.nominal_rate_hz;  // one physics tick a servo tick
    beam_ = std::make_unique<HapticBeam<2>>(model_, probe, &forces_, &forces_.get<0>(),
                                            physics_options);
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

 private:
  static ContactOptions Contact() {
    ContactOptions c;
    c.gap = kGap;
    c.separation = 2e-8;  // the asperities of a rough surface
    c.stiction = true;
    c.adhesion_energy = 0.02;
    return c;
  }

  BeamModel<2> model_;
  ForceTuple<SubstrateContact<2>, GapForce<2, CasimirPressure>> forces_;
  std::unique_ptr<HapticBeam<2>> beam_;
  std::unique_ptr<HapticLoop> loop_;
};

}  // namespace cosmems::example
