// The servo client that lets a hand touch the beam: the scaled force it asks for, the same
// history run to run with the physics in the servo tick, and the physics on its own thread
// (also run under ThreadSanitizer in cosmems_tsan_tests), and a stalled physics thread seen
// through a whole device.
#include "cosmems/haptics/haptic_loop.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "cosmems/haptics/haptic_beam.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "haptic_test_beam.hpp"

namespace cosmems {
namespace {

using test::kProbeCoupling;
using test::kProbeRadius;
using test::kReferenceThickness;

// 1 um of micro travel is 5 mm of hand travel; 1 uN is felt as 0.2 N.
HapticLoopOptions Options(PhysicsThread physics) {
  HapticLoopOptions options;
  options.scaling.position_scale = 5000.0;
  options.scaling.force_scale = 2e5;
  options.scaling.device_origin_m = Eigen::Vector3d(-0.1, 0.0, 0.0);  // the clamp 100 mm left
  options.physics = physics;
  return options;
}

// The stylus over the tip going down at 5 mm/s (1 um/s in the micro world): the probe's lowest
// point starts 2 um above the beam's upper face and touches it at 2 s.
DeviceState Stylus(const HapticLoopOptions& options, int tick) {
  DeviceState state;
  state.tick = static_cast<std::uint64_t>(tick);
  state.time_s = 1e-3 * tick;
  const double lowest_micro = 0.5 * kReferenceThickness + 2e-6 - 1e-6 * state.time_s;
  state.position_m = options.scaling.ToDevice(
      Eigen::Vector3d(test::kReferenceLength, lowest_micro + kProbeRadius, 0));
  state.velocity_m_s = Eigen::Vector3d(0.0, -5e-3, 0.0);
  return state;
}

std::vector<double> ServoForces(PhysicsThread physics, int ticks) {
  const BeamModel<2> model = test::HapticCantilever();
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
  const HapticLoopOptions options = Options(physics);
  HapticLoop loop(beam, options);
  std::vector<double> forces;
  for (int tick = 0; tick < ticks; ++tick) {
    ForceCommand command;
    loop.Tick(Stylus(options, tick), command);
    EXPECT_TRUE(command.valid);
    EXPECT_EQ(command.age_s, 0.0);
    forces.push_back(command.force_n.y());
  }
  return forces;
}

TEST(HapticLoopTest, TheHandFeelsTheScaledSeriesSpringAndTheSameForcesEveryRun) {
  const std::vector<double> first = ServoForces(PhysicsThread::kServo, 3000);
  EXPECT_EQ(first, ServoForces(PhysicsThread::kServo, 3000));  // bit for bit
  const double k_tip = test::ReferenceTipStiffness();
  const double series = kProbeCoupling * k_tip / (kProbeCoupling + k_tip);
  for (int tick : {1500, 2500, 2999}) {
    const double depth = std::max(0.0, 1e-6 * (1e-3 * tick) - 2e-6);  // micro depth
    // Quasi-static: the probe descends 1 nm a tick, far slower than the beam's 14.5 us period.
    EXPECT_NEAR(first[static_cast<std::size_t>(tick)], 2e5 * series * depth,
                1e-6 * 2e5 * series * 1e-6 + 1e-12);
  }
}

TEST(HapticLoopTest, PhysicsOnItsOwnThreadFeedsTheServoAndTheDisplay) {
  const BeamModel<2> model = test::HapticCantilever();
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
  const HapticLoopOptions options = Options(PhysicsThread::kOwn);
  HapticLoop loop(beam, options);
  loop.StartPhysics();
  std::atomic<bool> done{false};
  long frames = 0;
  double last_time = -1.0;
  bool time_went_back = false;
  std::thread display([&] {
    while (!done) {
      if (loop.UpdateFrame()) {
        ++frames;
        time_went_back |= loop.frame().time_s < last_time;
        last_time = loop.frame().time_s;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(33));
    }
  });
  int valid = 0;
  double force = 0.0;
  for (int tick = 0; tick < 3000; tick += 10) {  // a 100 Hz "servo loop", 10 ms of hand a tick
    ForceCommand command;
    loop.Tick(Stylus(options, tick), command);
    valid += command.valid;
    force = command.force_n.y();
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  done = true;
  display.join();
  loop.StopPhysics();
  EXPECT_GT(valid, 0);
  EXPECT_GT(frames, 0);
  EXPECT_FALSE(time_went_back);
  EXPECT_GT(loop.physics_stats().ticks, 0u);
  EXPECT_EQ(loop.failed_ticks(), 0u);
  // The last command came from a local model at most a few ticks old: within 10 % of the force
  // at the stylus's final depth (the model is exact in depth; only its age differs).
  const double k_tip = test::ReferenceTipStiffness();
  const double expected =
      2e5 * kProbeCoupling * k_tip / (kProbeCoupling + k_tip) * (1e-6 * 2.99 - 2e-6);
  EXPECT_NEAR(force, expected, 0.1 * expected);
}

/// The stylus held still where Stylus() is at `tick`.
class HeldStylus final : public Trajectory {
 public:
  HeldStylus(const HapticLoopOptions& options, int tick)
      : position_m_(Stylus(options, tick).position_m) {}
  Eigen::Vector3d Position(double) const override { return position_m_; }
  double Duration() const override { return 10.0; }

 private:
  Eigen::Vector3d position_m_;
};

// The whole loop (scripted device, safety layer, HapticLoop with its physics thread) when the
// physics stalls: the model the servo renders ages, and once it is older than max_model_age_s
// the force comes down to zero. A device started again (its clock back at 0) must not take the
// model of the run before for a fresh one either.
TEST(HapticLoopTest, AStalledPhysicsThreadAndADeviceRestartBringTheForceToZero) {
  const BeamModel<2> model = test::HapticCantilever();
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
  const HapticLoopOptions options = Options(PhysicsThread::kOwn);
  HapticLoop loop(beam, options);
  ScriptedOptions scripted;
  scripted.clock = ScriptedClock::kManual;
  scripted.safety.ramp_in_s = 0.0;
  scripted.safety.slew_limit_n_per_s = 1e4;  // 10 N a tick: the force follows at once
  ScriptedDevice device(std::make_unique<HeldStylus>(options, 2500), scripted);  // 0.5 um deep
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  loop.StartPhysics();
  ASSERT_EQ(device.Start(loop), DeviceStatus::kOk);
  // The device ticks no faster than the physics thread, so the model stays fresh.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (device.Recorded().empty() || device.Recorded().back().force_n.y() <= 0.0) {
    ASSERT_LT(std::chrono::steady_clock::now(), give_up) << "no force from the physics thread";
    device.Step(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const long stale_before = device.safety_counters().stale_forces;
  loop.StopPhysics();  // the physics stalls; the servo ticks on
  const std::uint64_t stalled_at = device.ticks();
  device.Step(100);
  std::vector<ScriptedSample> samples = device.Recorded();
  EXPECT_GT(samples[stalled_at].force_n.y(), 0.0);  // a model 1 ms old is still rendered
  EXPECT_EQ(samples.back().force_n.norm(), 0.0);
  // 10 ms of age at 1 ms a tick, then every tick stale.
  EXPECT_GE(device.safety_counters().stale_forces - stale_before, 85);

  device.Stop();
  ASSERT_EQ(device.Start(loop), DeviceStatus::kOk);
  device.Step(100);
  samples = device.Recorded();
  ASSERT_EQ(samples.size(), 100u);
  for (const ScriptedSample& s : samples) ASSERT_EQ(s.force_n.norm(), 0.0) << s.time_s;
  device.Stop();
}

// The panel's "Reset Failure": asked for from another thread while the beam lies stuck where the
// stylus laid it (pressed at the tip, swept to midspan, lifted), the next physics tick frees it.
TEST(HapticLoopTest, AResetRequestedFromAnotherThreadFreesTheStuckBeam) {
  const BeamModel<2> model = test::HapticCantilever();
  test::HapticSurface forces = test::MakeHapticSurface(model);
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, 50.0}, &forces, &forces.get<0>());
  const HapticLoopOptions options = Options(PhysicsThread::kServo);
  HapticLoop loop(beam, options);
  int tick = 0;
  auto touch = [&](double x, double depth) {
    DeviceState state;
    state.tick = static_cast<std::uint64_t>(tick);
    state.time_s = 1e-3 * tick++;
    state.position_m = options.scaling.ToDevice(
        Eigen::Vector3d(x, 0.5 * kReferenceThickness - depth + kProbeRadius, 0.0));
    ForceCommand command;
    loop.Tick(state, command);
  };
  const double length = test::kReferenceLength, depth = 3e-6;
  for (int i = 0; i <= 200; ++i) touch(length, depth * i / 200.0);
  for (int i = 0; i <= 200; ++i) touch(length * (1.0 - 0.5 * i / 200.0), depth);
  for (int i = 0; i <= 200; ++i) touch(0.5 * length, depth - 8e-6 * i / 200.0);
  ASSERT_TRUE(loop.UpdateFrame());
  ASSERT_TRUE(loop.frame().contact.Stuck());
  touch(0.5 * length, -5e-6);  // no request yet: still stuck
  loop.UpdateFrame();
  ASSERT_TRUE(loop.frame().contact.Stuck());

  std::thread panel([&loop] { loop.RequestReset(); });
  panel.join();
  touch(0.5 * length, -5e-6);
  ASSERT_TRUE(loop.UpdateFrame());
  EXPECT_EQ(loop.frame().contact.state, ContactState::kFree);
  EXPECT_LT(std::abs(loop.frame().deflection_m[20]), 1e-3 * test::kHapticGap);
  EXPECT_EQ(loop.failed_ticks(), 0u);
}

}  // namespace
}  // namespace cosmems
