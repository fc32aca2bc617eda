#pragma once

// The paper's scene touched through the whole servo path, as the passivity and stylus tests
// drive it: the reference cantilever with the paper's surface, a probe coupled at 25 times the
// tip's stiffness, a PHANTOM Omni's specs with the command line's hand scaling, and a HapticLoop
// with the physics in the servo tick. Not movable: the beam and the loop hold references to the
// members before them.
#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/haptic_beam.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "haptic_test_beam.hpp"

namespace cosmems::test {

struct ReferenceTouch {
  explicit ReferenceTouch(const HapticPhysicsOptions& physics = {})
      : forces(MakeHapticSurface(model)),
        beam(model, ProbeOptions{kProbeRadius, coupling}, &forces, &forces.get<0>(), physics),
        loop(beam, LoopOptions(specs, coupling)) {}

  static HapticLoopOptions LoopOptions(const DeviceSpecs& specs, double coupling) {
    HapticLoopOptions options;
    options.physics = PhysicsThread::kServo;  // the tests drive unpaced (manual) devices
    options.scaling = ReferenceHandScaling(specs, coupling);
    return options;
  }

  BeamModel<2> model = HapticCantilever();
  double coupling = 25.0 * ReferenceTipStiffness();
  DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  HapticSurface forces;
  HapticBeam<2> beam;
  HapticLoop loop;
};

}  // namespace cosmems::test
