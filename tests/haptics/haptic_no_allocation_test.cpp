// The servo tick of the haptic scene allocates nothing: the stylus presses the tip of the
// cantilever's netlist (as the command line touches it) onto the substrate (contact, stiction,
// Casimir), holds and lifts off, with the physics inside the tick and the safety layer after it;
// and the same for a device, a folded flexure's shuttle pressed toward the substrate under the
// Casimir force.
#include <gtest/gtest.h>

#include <string>

#include "allocation_counter.hpp"
#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/haptics/safety_layer.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "haptics/haptic_test_beam.hpp"
#include "structure/test_frames.hpp"

namespace cosmems {
namespace {

// The full model's path and the modal one (eight modes, Q = 100).
class HapticNoAllocationTest : public ::testing::TestWithParam<TimePath> {};

TEST_P(HapticNoAllocationTest, ServoTicksThroughPressStickAndLiftAllocateNothing) {
  const FrameModel model(test::HapticCantileverNetlist());
  test::HapticNetlistSurface forces(model);
  HapticPhysicsOptions physics;
  physics.path = GetParam();
  physics.modes = 8;
  physics.damping = DampingModel::QualityFactor(100);
  HapticStructure beam(model, ProbeOptions{2e-6, 5.0}, &forces.all, &forces.contact, physics);
  HapticLoopOptions options;
  options.physics = PhysicsThread::kServo;  // the test ticks the loop itself, unpaced
  options.scaling.position_scale = 5000.0;
  options.scaling.force_scale = 2e5;
  HapticLoop loop(beam, options);
  SafetyLayer safety(SafetyOptions{}, BuiltInSpecs("PHANTOM Omni"));
  int tick = 0;
  // 300 ticks down to 4 um below the upper face (past the 2 um gap), 300 back up 3 um clear.
  const long allocations = test::AllocationsDuring(600, [&] {
    const double s = tick < 300 ? tick / 300.0 : 1.0 - 1.75 * (tick - 300) / 300.0;
    DeviceState state;
    state.tick = static_cast<std::uint64_t>(tick);
    state.time_s = 1e-3 * tick++;
    state.position_m = options.scaling.ToDevice(
        Eigen::Vector3d(test::kReferenceLength, 1e-6 - 4e-6 * s + 2e-6, 0.0));
    ForceCommand command;
    loop.Tick(state, command);
    (void)safety.Filter(state, command);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(loop.failed_ticks(), 0u);
  ASSERT_TRUE(loop.UpdateFrame());
  EXPECT_GE(loop.frame().events.stuck, 1);
}

TEST_P(HapticNoAllocationTest, ADevicesTicksAllocateNothing) {
  const FrameModel model(test::FoldedFlexure(100e-6, 4));
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{}, FrameGapOptions{2e-6});
  ContactOptions substrate;
  substrate.gap = 2e-6;
  substrate.separation = 2e-8;
  // On the full model, adhesion too weak to hold the shuttle against its springs once the probe
  // lifts: it sticks, then springs off (0.2 um above the substrate: at 20 nm the Casimir pull
  // alone holds it down). The modal path takes no adhesion on a device.
  const bool stiction = GetParam() == TimePath::kNewmarkFamily;
  if (stiction) {
    substrate.separation = 2e-7;
    substrate.stiction = true;
    substrate.adhesion_energy = 1e-6;
  }
  FrameSubstrateContact contact(model, substrate);
  ForceSum forces;
  forces.Add(casimir);
  forces.Add(contact);
  HapticPhysicsOptions physics;
  physics.path = GetParam();
  physics.modes = 8;
  physics.damping = DampingModel::QualityFactor(100);
  HapticStructure structure(model, ProbeOptions{2e-6, 50.0}, &forces, &contact, physics);
  HapticFrame frame = structure.MakeFrame();
  int tick = 0;
  // 300 ticks from 1 um above the shuttle's upper face to 3 um into it, the shuttle pressed onto
  // the substrate 2 um below (and stuck), 300 back up, each published to the display's frame.
  const long allocations = test::AllocationsDuring(600, [&] {
    const double s = tick < 300 ? tick / 300.0 : 1.0 - (tick - 300) / 300.0;
    const Eigen::Vector3d probe(5e-6, 1e-6 + 2e-6 + 1e-6 - 4e-6 * s, 3e-6);
    (void)structure.Advance(probe, 1e-3 * tick++);
    structure.Fill(frame);
  });
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(structure.status(), Status::kOk);
  EXPECT_EQ(frame.events.contacts, 1);
  EXPECT_EQ(frame.events.stuck, stiction ? 1 : 0);
  EXPECT_EQ(frame.events.releases, stiction ? 1 : 0);
}

std::string PathName(const ::testing::TestParamInfo<TimePath>& path) {
  return path.param == TimePath::kModal ? "Modal" : "FullModel";
}

INSTANTIATE_TEST_SUITE_P(Paths, HapticNoAllocationTest,
                         ::testing::Values(TimePath::kNewmarkFamily, TimePath::kModal), PathName);

}  // namespace
}  // namespace cosmems
