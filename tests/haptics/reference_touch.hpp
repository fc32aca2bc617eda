#pragma once

// The paper's scene touched through the whole servo path, as the passivity and stylus tests
// drive it: the reference cantilever's netlist (as the command line touches it) with the paper's
// surface, a probe coupled at 25 times the
// tip's stiffness, a PHANTOM Omni's specs with the command line's hand scaling, and a HapticLoop
// with the physics in the servo tick. Not movable: the beam and the loop hold references to the
// members before them.
#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "haptic_test_beam.hpp"

namespace cosmems::test {

struct ReferenceTouch {
  explicit ReferenceTouch(const HapticPhysicsOptions& physics = {})
      : forces(model),
        beam(model, ProbeOptions{kProbeRadius, coupling}, &forces.all, &forces.contact, physics),
        loop(beam, LoopOptions(specs, coupling)) {}

  static HapticLoopOptions LoopOptions(const DeviceSpecs& specs, double coupling) {
    HapticLoopOptions options;
    options.physics = PhysicsThread::kServo;  // the tests drive unpaced (manual) devices
    options.scaling = ReferenceHandScaling(specs, coupling);
    return options;
  }

  FrameModel model{HapticCantileverNetlist()};
  double coupling = 25.0 * ReferenceTipStiffness();
  DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  HapticNetlistSurface forces;
  HapticStructure beam;
  HapticLoop loop;
};

}  // namespace cosmems::test
