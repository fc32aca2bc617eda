// The servo client that lets a hand touch the beam (the cantilever's netlist): the scaled force it
// asks for, the same history run to run with the physics in the servo tick, and the physics on its
// own thread (also run under ThreadSanitizer in cosmems_tsan_tests), a stalled physics thread seen
// through a whole device, the paced devices' refusal of physics in the tick, and physics that
// fails without saying so.
#include "cosmems/haptics/haptic_loop.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <new>
#include <thread>
#include <vector>

#include "cosmems/haptics/haptic_structure.hpp"
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
  const FrameModel model(test::HapticCantileverNetlist());
  HapticStructure beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
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
  const FrameModel model(test::HapticCantileverNetlist());
  HapticStructure beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
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
// physics stalls: the model the servo renders ages in wall time, and once it is older than
// max_model_age_s the force comes down to zero, whatever the device's own clock says (this one
// ticks only when told). A device started again must not take the model of the run before for a
// fresh one either.
TEST(HapticLoopTest, AStalledPhysicsThreadAndADeviceRestartBringTheForceToZero) {
  const FrameModel model(test::HapticCantileverNetlist());
  HapticStructure beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
  const HapticLoopOptions options = Options(PhysicsThread::kOwn);
  HapticLoop loop(beam, options);
  ScriptedOptions scripted;
  scripted.clock = ScriptedClock::kManual;
  scripted.safety.ramp_in_s = 0.0;
  scripted.safety.slew_limit_n_per_s = 1e4;  // 10 N a tick: the force follows at once
  // 50 ms: far above a physics tick's period and join, even on a loaded machine.
  scripted.safety.max_model_age_s = 0.05;
  ScriptedDevice device(std::make_unique<HeldStylus>(options, 2500), scripted);  // 0.5 um deep
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  loop.StartPhysics();
  ASSERT_EQ(device.Start(loop), DeviceStatus::kOk);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (device.Recorded().empty() || device.Recorded().back().force_n.y() <= 0.0) {
    ASSERT_LT(std::chrono::steady_clock::now(), give_up) << "no force from the physics thread";
    device.Step(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  const long stale_before = device.safety_counters().stale_forces;
  loop.StopPhysics();  // the physics stalls; the servo ticks on
  const std::uint64_t stalled_at = device.ticks();
  // At least 1 ms of wall time a tick: tick k after the stall renders a model at least k ms old.
  for (int tick = 0; tick < 100; ++tick) {
    device.Step(1);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  std::vector<ScriptedSample> samples = device.Recorded();
  EXPECT_GT(samples[stalled_at].force_n.y(), 0.0);  // a model a few ms old is still rendered
  EXPECT_EQ(samples.back().force_n.norm(), 0.0);
  // Every tick from the 50th on renders a model over 50 ms old.
  EXPECT_GE(device.safety_counters().stale_forces - stale_before, 50);

  device.Stop();
  ASSERT_EQ(device.Start(loop), DeviceStatus::kOk);
  device.Step(100);
  samples = device.Recorded();
  ASSERT_EQ(samples.size(), 100u);
  for (const ScriptedSample& s : samples) ASSERT_EQ(s.force_n.norm(), 0.0) << s.time_s;
  device.Stop();
}

// The physics on its own thread is the default; inside the tick nothing watches how long the
// physics takes, so a paced device (a script on the wall clock, a real device's scheduler)
// refuses it, and an unpaced one (as fast as possible) takes it.
TEST(HapticLoopTest, APacedDeviceRefusesPhysicsInsideTheServoTick) {
  EXPECT_EQ(HapticLoopOptions{}.physics, PhysicsThread::kOwn);
  const FrameModel model(test::HapticCantileverNetlist());
  HapticStructure beam(model, ProbeOptions{kProbeRadius, kProbeCoupling}, nullptr, nullptr);
  HapticLoop in_tick(beam, Options(PhysicsThread::kServo));
  const HapticLoopOptions options = Options(PhysicsThread::kOwn);
  ScriptedOptions paced;
  paced.clock = ScriptedClock::kPaced;
  ScriptedDevice device(std::make_unique<HeldStylus>(options, 0), paced);
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(device.Start(in_tick), DeviceStatus::kRefused);
  EXPECT_FALSE(device.is_running());
  ScriptedOptions fast;
  fast.clock = ScriptedClock::kManual;
  ScriptedDevice unpaced(std::make_unique<HeldStylus>(options, 0), fast);
  ASSERT_EQ(unpaced.Open(), DeviceStatus::kOk);
  EXPECT_EQ(unpaced.Start(in_tick), DeviceStatus::kOk);
  unpaced.Stop();
}

// Physics that goes wrong in ways its status does not say: a model with a NaN stiffness, and a
// reset that throws (it may allocate). Each is a failed tick with an invalid model, inside a
// noexcept tick, and the next good tick renders again.
class FaultyPhysics final : public HapticPhysics {
 public:
  enum class Fault { kNone, kNaNStiffness, kNaNNormal, kThrowOnReset };
  Fault fault = Fault::kNone;
  Status Advance(const Eigen::Vector3d& probe_m, double source_time_s) override {
    model_ = LocalModel{};
    model_.probe_m = probe_m;
    model_.source_time_s = source_time_s;
    model_.force_n = 1e-6;
    model_.stiffness_n_per_m = 1.0;
    model_.valid = true;
    if (fault == Fault::kNaNStiffness) model_.stiffness_n_per_m = std::nan("");
    if (fault == Fault::kNaNNormal) model_.normal.x() = std::nan("");
    return Status::kOk;
  }
  Status Reset() override {
    if (fault == Fault::kThrowOnReset) throw std::bad_alloc();
    return Status::kOk;
  }
  const LocalModel& local_model() const override { return model_; }
  double tick_s() const override { return 1e-3; }
  int DofCount() const override { return 0; }
  HapticFrame MakeFrame() const override { return HapticFrame{}; }
  void Fill(HapticFrame&) const override {}

 private:
  LocalModel model_;
};

TEST(HapticLoopTest, ANonFiniteModelOrAThrowingResetIsAFailedTick) {
  FaultyPhysics physics;
  HapticLoopOptions options = Options(PhysicsThread::kServo);
  options.reset_button = 0;
  HapticLoop loop(physics, options);
  DeviceState state;
  auto tick = [&](FaultyPhysics::Fault fault, std::uint32_t buttons) {
    physics.fault = fault;
    state.buttons = buttons;
    ForceCommand command;
    loop.Tick(state, command);
    state.time_s += 1e-3;
    return command;
  };
  EXPECT_TRUE(tick(FaultyPhysics::Fault::kNone, 0).valid);
  EXPECT_FALSE(tick(FaultyPhysics::Fault::kNaNStiffness, 0).valid);
  EXPECT_FALSE(tick(FaultyPhysics::Fault::kNaNNormal, 0).valid);
  EXPECT_FALSE(tick(FaultyPhysics::Fault::kThrowOnReset, 1u).valid);  // the button's press
  EXPECT_EQ(loop.failed_ticks(), 3u);
  const ForceCommand good = tick(FaultyPhysics::Fault::kNone, 0);
  EXPECT_TRUE(good.valid);
  EXPECT_TRUE(good.force_n.allFinite());
  EXPECT_EQ(loop.failed_ticks(), 3u);
}

// After a stall the physics thread does not run the ticks it missed back to back: their
// deadlines are dropped. A sleep of at least 30 ms at 1 kHz passes at least 29 of them.
TEST(PeriodicDeadlineTest, SkippingDropsTheDeadlinesAStallPassed) {
  PeriodicDeadline skip(1000.0, CatchUp::kSkip);
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  skip.SleepUntilNext();
  EXPECT_GE(skip.skipped(), 29u);
  PeriodicDeadline all(1000.0);  // the device clock's kind keeps every tick
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  all.SleepUntilNext();
  EXPECT_EQ(all.skipped(), 0u);
}

// The panel's "Reset Failure": asked for from another thread while the beam lies stuck where the
// stylus laid it (pressed at the tip, swept to midspan, lifted), the next physics tick frees it.
TEST(HapticLoopTest, AResetRequestedFromAnotherThreadFreesTheStuckBeam) {
  const FrameModel model(test::HapticCantileverNetlist());
  test::HapticNetlistSurface forces(model);
  HapticStructure beam(model, ProbeOptions{kProbeRadius, 50.0}, &forces.all, &forces.contact);
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
  EXPECT_LT(std::abs(test::NetlistTipDeflection(model, loop.frame())), 1e-3 * test::kHapticGap);
  EXPECT_EQ(loop.failed_ticks(), 0u);
}

}  // namespace
}  // namespace cosmems
