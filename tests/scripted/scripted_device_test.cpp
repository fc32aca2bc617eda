#include "cosmems/scripted/scripted_device.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cosmems/haptics/safety_layer.hpp"
#include "cosmems/scripted/built_in_trajectory.hpp"
#include "cosmems/scripted/csv_trajectory.hpp"
#include "test_clients.hpp"

namespace cosmems {
namespace {

/// Two presses of 0.5 s: 1001 ticks at 1 kHz.
MotionShape ShortPress() {
  MotionShape shape;
  shape.start_m = Eigen::Vector3d(0.002, 0.01, -0.003);
  shape.depth_m = 0.02;
  shape.period_s = 0.5;
  shape.cycles = 2;
  return shape;
}

ScriptedOptions WithClock(ScriptedClock clock, HandModel hand = HandModel::kRigid) {
  ScriptedOptions options;
  options.clock = clock;
  options.hand = hand;
  return options;
}

std::unique_ptr<const Trajectory> Press(const MotionShape& shape = ShortPress()) {
  return MakeBuiltInTrajectory("press", shape);
}

/// A wall 5 mm above the bottom of ShortPress(): pressed hard enough to reach the force limit.
WallClient PressedWall() { return WallClient(ShortPress().start_m.y() - 0.015, 700.0); }

std::vector<ScriptedSample> RunManual(const ScriptedOptions& options, ServoClient& client) {
  ScriptedDevice device(Press(), options);
  EXPECT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(device.Start(client), DeviceStatus::kOk);
  while (device.Step(97) > 0) {
  }
  EXPECT_TRUE(device.Done());
  return device.Recorded();
}

bool SameBits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

/// Every field of every row equal to the bit.
void ExpectBitIdentical(const std::vector<ScriptedSample>& a,
                        const std::vector<ScriptedSample>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_TRUE(std::memcmp(&a[i].time_s, &b[i].time_s, sizeof(double)) == 0) << i;
    ASSERT_TRUE(SameBits(a[i].position_m, b[i].position_m)) << i;
    ASSERT_TRUE(SameBits(a[i].velocity_m_s, b[i].velocity_m_s)) << i;
    ASSERT_TRUE(SameBits(a[i].force_n, b[i].force_n)) << i;
  }
}

double LargestForce(const std::vector<ScriptedSample>& samples) {
  double largest = 0.0;
  for (const ScriptedSample& s : samples) largest = std::max(largest, s.force_n.norm());
  return largest;
}

std::string TempPath(const std::string& suffix) {
  return ::testing::TempDir() + "cosmems_scripted_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + suffix;
}

TEST(ScriptedDeviceTest, ManualClockTicksTheWholeScriptOnTickTime) {
  WallClient client = PressedWall();
  ScriptedDevice device(Press(), WithClock(ScriptedClock::kManual));
  EXPECT_EQ(device.Step(10), 0u);  // not started
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(device.specs().model, "PHANTOM Omni");
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  EXPECT_EQ(device.Step(300), 300u);
  EXPECT_EQ(device.ticks(), 300u);
  EXPECT_FALSE(device.Done());
  EXPECT_EQ(device.Step(1000000), 701u);  // ticks 0 .. 1000 cover [0 s, 1 s]
  EXPECT_TRUE(device.Done());
  EXPECT_EQ(device.Step(1), 0u);
  device.WaitUntilDone();  // returns at once: no thread

  const std::vector<ScriptedSample> samples = device.Recorded();
  ASSERT_EQ(samples.size(), 1001u);
  for (std::size_t n = 0; n < samples.size(); ++n) {
    const double t = static_cast<double>(n) / 1000.0;
    ASSERT_EQ(samples[n].time_s, t);
    // The rigid hand is exactly on the script, with the backward-difference velocity.
    const Eigen::Vector3d p = device.trajectory().Position(t);
    ASSERT_EQ(samples[n].position_m, p) << n;
    const Eigen::Vector3d v =
        n == 0 ? Eigen::Vector3d::Zero()
               : Eigen::Vector3d((p - device.trajectory().Position((n - 1.0) / 1000.0)) * 1000.0);
    ASSERT_EQ(samples[n].velocity_m_s, v) << n;
  }
  device.Stop();
  EXPECT_EQ(device.stats().ticks, 1001u);
  EXPECT_FALSE(device.stats().paced);
  EXPECT_FALSE(device.stats().realtime);
}

TEST(ScriptedDeviceTest, ManualRunsAreBitIdentical) {
  for (HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
    SCOPED_TRACE(hand == HandModel::kRigid ? "rigid" : "spring");
    WallClient first_client = PressedWall();
    WallClient second_client = PressedWall();
    const auto first = RunManual(WithClock(ScriptedClock::kManual, hand), first_client);
    const auto second = RunManual(WithClock(ScriptedClock::kManual, hand), second_client);
    ExpectBitIdentical(first, second);
    // The wall was pressed (else identical zero forces would prove nothing).
    EXPECT_GT(LargestForce(first), 0.5);
  }
}

TEST(ScriptedDeviceTest, RestartReplaysFromTheFirstTick) {
  WallClient client = PressedWall();
  const ScriptedOptions options = WithClock(ScriptedClock::kManual, HandModel::kSpring);
  const auto fresh = RunManual(options, client);
  ScriptedDevice device(Press(), options);
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  device.Step(640);  // stop in the middle of a press, force on
  device.Stop();
  EXPECT_EQ(device.Step(1), 0u);  // stopped
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  EXPECT_EQ(device.ticks(), 0u);
  while (device.Step(1000) > 0) {
  }
  ExpectBitIdentical(device.Recorded(), fresh);
}

TEST(ScriptedDeviceTest, FastClockGivesTheManualHistory) {
  for (HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
    SCOPED_TRACE(hand == HandModel::kRigid ? "rigid" : "spring");
    WallClient manual_client = PressedWall();
    const auto manual = RunManual(WithClock(ScriptedClock::kManual, hand), manual_client);

    WallClient client = PressedWall();
    ScriptedDevice device(Press(), WithClock(ScriptedClock::kFast, hand));
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
    EXPECT_THROW(device.Step(1), std::logic_error);  // the thread owns the ticks
    device.WaitUntilDone();
    EXPECT_TRUE(device.Done());
    device.Stop();
    EXPECT_EQ(device.stats().ticks, 1001u);
    ExpectBitIdentical(device.Recorded(), manual);
  }
}

TEST(ScriptedDeviceTest, PacedClockRunsToTheEndOfTheScript) {
  MotionShape shape = ShortPress();
  shape.period_s = 0.05;
  shape.cycles = 1;  // 51 ticks
  WallClient client = PressedWall();
  ScriptedDevice device(Press(shape), WithClock(ScriptedClock::kPaced));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  // Whether SCHED_FIFO was granted depends on the machine; either way the outcome is stated.
  EXPECT_FALSE(device.realtime_note().empty());
  EXPECT_NE(device.realtime_note(), "not started");
  device.WaitUntilDone();
  EXPECT_TRUE(device.Done());
  EXPECT_EQ(device.ticks(), 51u);
  device.Stop();
  EXPECT_EQ(device.stats().ticks, 51u);
  EXPECT_TRUE(device.stats().paced);
  ASSERT_EQ(device.Recorded().size(), 51u);
  EXPECT_EQ(device.Recorded().back().time_s, 0.05);
}

TEST(ScriptedDeviceTest, PacedClockStopsInTheMiddle) {
  MotionShape shape = ShortPress();
  shape.cycles = 200;  // 100 s: it must be stopped, not finish
  WallClient client = PressedWall();
  ScriptedDevice device(Press(shape), WithClock(ScriptedClock::kPaced));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  // Wait for ticks without assuming any speed (a loaded machine may be slow to schedule us).
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (device.ticks() < 5 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  device.Stop();
  const std::uint64_t ticks = device.ticks();
  EXPECT_GE(ticks, 5u);
  EXPECT_FALSE(device.Done());
  EXPECT_FALSE(device.is_running());
  device.WaitUntilDone();  // the thread has ended: returns at once
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(device.ticks(), ticks);  // nothing ticks after Stop()
  EXPECT_EQ(device.Recorded().size(), ticks);
}

/// Pushes up with 0.8 N whatever the stylus does: a force that is on when the loop stops. (Run
/// with the passivity controller off, which would damp it while the stylus rises.)
class PushClient final : public ServoClient {
 public:
  void Tick(const DeviceState&, ForceCommand& command) noexcept override {
    command.force_n = Eigen::Vector3d(0.0, 0.8, 0.0);
  }
};

/// The rows after `from`: each a slew step or less from the one before, the last zero, and no
/// more of them than a ramp from the limit takes.
void ExpectRampFrom(const std::vector<ScriptedSample>& samples, std::size_t from,
                    const ScriptedDevice& device) {
  const double slew = SafetyLayer(SafetyOptions{}, device.specs()).slew_per_tick();
  ASSERT_GT(from, 0u);
  ASSERT_GT(samples.size(), from);
  EXPECT_NEAR(samples[from - 1].force_n.y(), 0.8, 1e-12);  // pushing when the stop came
  for (std::size_t n = from; n < samples.size(); ++n) {
    EXPECT_LE((samples[n].force_n - samples[n - 1].force_n).norm(), slew * (1.0 + 1e-12)) << n;
  }
  EXPECT_EQ(samples.back().force_n.norm(), 0.0);
  EXPECT_EQ(samples.size() - from, 8u);  // 0.8 N at 0.1 N a tick
  EXPECT_EQ(device.safety_counters().ramp_down_ticks, static_cast<long>(samples.size() - from));
}

// Stopping the loop, or reaching the script's end, does not drop the force from where it is:
// the device brings it down to zero along the slew limit while the hand holds still, on every
// clock, and records the ramp's ticks.
TEST(ScriptedDeviceTest, StopAndTheScriptsEndRampTheForceDown) {
  PushClient client;
  auto undamped = [](ScriptedClock clock) {
    ScriptedOptions options = WithClock(clock);
    options.safety.passivity_control = false;
    return options;
  };
  {
    ScriptedDevice device(Press(), undamped(ScriptedClock::kManual));
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
    ASSERT_EQ(device.Step(640), 640u);  // past the 0.5 s ramp-in: 0.8 N
    device.Stop();
    EXPECT_FALSE(device.Done());  // stopped, not finished
    ExpectRampFrom(device.Recorded(), 640, device);
  }
  for (ScriptedClock clock : {ScriptedClock::kManual, ScriptedClock::kFast}) {
    ScriptedDevice device(Press(), undamped(clock));
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
    if (clock == ScriptedClock::kManual) {
      while (device.Step(97) > 0) {
      }
    } else {
      device.WaitUntilDone();
    }
    EXPECT_TRUE(device.Done());
    device.Stop();
    ExpectRampFrom(device.Recorded(), 1001, device);  // the script's 1001 ticks, then the ramp
  }
}

// The figures are read from other threads while the servo thread writes them (run under
// ThreadSanitizer too): the tick count only grows and no snapshot shows a force above the limit.
TEST(ScriptedDeviceTest, StatsAreReadWhileTheLoopRuns) {
  MotionShape shape = ShortPress();
  shape.cycles = 200;
  PushClient client;
  ScriptedDevice device(Press(shape), WithClock(ScriptedClock::kFast));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  std::vector<std::thread> readers;
  std::atomic<bool> went_back{false};
  for (int r = 0; r < 2; ++r) {
    readers.emplace_back([&] {
      std::uint64_t last = 0;
      for (int i = 0; i < 200; ++i) {
        const std::uint64_t ticks = device.stats().ticks;
        if (ticks < last) went_back = true;
        last = ticks;
        if (device.safety_counters().max_force_n > device.force_limit_n() * (1.0 + 1e-12)) {
          went_back = true;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
    });
  }
  for (std::thread& reader : readers) reader.join();
  device.Stop();
  EXPECT_FALSE(went_back);
  EXPECT_GT(device.stats().ticks, 0u);
  EXPECT_LE(device.safety_counters().ramp_down_ticks, device.MaxRampDownTicks());
}

TEST(ScriptedDeviceTest, DestructorStopsARunningThread) {
  MotionShape shape = ShortPress();
  shape.cycles = 200;
  WallClient client = PressedWall();
  for (ScriptedClock clock : {ScriptedClock::kPaced, ScriptedClock::kFast}) {
    ScriptedDevice device(Press(shape), WithClock(clock));
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  }  // joins the servo thread; a thread left running would abort the test
}

// The script takes the tip 2 mm below a wall of the Omni's renderable stiffness. Held by a hand
// spring of k_h = 300 N/m, the tip must stop where the two springs balance, k_h (2 mm - p) =
// k_w p, at p = 0.6 mm, while a rigid hand goes all the way through.
TEST(ScriptedDeviceTest, SpringHandStopsAtAStiffWall) {
  MotionShape shape;
  shape.start_m = Eigen::Vector3d(0.0, 0.01, 0.0);
  shape.depth_m = 0.02;
  shape.period_s = 2.0;
  shape.cycles = 1;
  const double wall_y = shape.start_m.y() - shape.depth_m + 0.002;
  const double wall_k = 700.0;
  // End of the hold (40 % to 70 % of the period), 0.75 s after the tip reached the wall.
  const std::size_t settled = 1390;

  std::vector<ScriptedSample> rows[2];
  for (HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
    WallClient client(wall_y, wall_k);
    ScriptedDevice device(Press(shape), WithClock(ScriptedClock::kManual, hand));
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
    device.Step(settled + 1);
    rows[hand == HandModel::kSpring] = device.Recorded();
  }
  const ScriptedSample& rigid = rows[0][settled];
  const ScriptedSample& spring = rows[1][settled];
  EXPECT_EQ(rigid.position_m.y(), wall_y - 0.002);

  const double k_h = HandSpring{}.stiffness_n_per_m;
  const double penetration = k_h * 0.002 / (k_h + wall_k);
  // By then the contact oscillation (hand damping alone: decay rate b / 2m = 22 1/s) has shrunk
  // by e^-16, so the tip sits at the balance point up to rounding. 1 um (0.2 % of the
  // penetration) is far above that residue and far below the 1.4 mm of a hand ignoring the wall.
  EXPECT_NEAR(spring.position_m.y(), wall_y - penetration, 1e-6);
  EXPECT_NEAR(spring.force_n.y(), wall_k * penetration, wall_k * 1e-6);
  EXPECT_NEAR(spring.velocity_m_s.norm(), 0.0, 1e-4);
  // Nothing pushes sideways: x and z stay on the script.
  EXPECT_NEAR(spring.position_m.x(), shape.start_m.x(), 1e-15);
  EXPECT_NEAR(spring.position_m.z(), shape.start_m.z(), 1e-15);
}

/// On the script except for `nan_from` <= t < `nan_to`, where y is NaN.
class GappyTrajectory final : public Trajectory {
 public:
  GappyTrajectory(double nan_from, double nan_to) : nan_from_(nan_from), nan_to_(nan_to) {}
  Eigen::Vector3d Position(double t_s) const override {
    const double y = t_s >= nan_from_ && t_s < nan_to_ ? std::numeric_limits<double>::quiet_NaN()
                                                       : 0.01 - 0.01 * t_s;
    return Eigen::Vector3d(0.001, y, 0.002 * t_s);
  }
  double Duration() const override { return 0.5; }

 private:
  double nan_from_;
  double nan_to_;
};

TEST(ScriptedDeviceTest, NanScriptReachesTheStateAndTheHandRecovers) {
  for (HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
    SCOPED_TRACE(hand == HandModel::kRigid ? "rigid" : "spring");
    WallClient client(-1.0, 700.0);  // far below: no contact
    ScriptedDevice device(std::make_unique<GappyTrajectory>(0.1, 0.2),
                          WithClock(ScriptedClock::kManual, hand));
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
    while (device.Step(100) > 0) {
    }
    const auto samples = device.Recorded();
    ASSERT_EQ(samples.size(), 501u);
    for (std::size_t n = 0; n < samples.size(); ++n) {
      const Eigen::Vector3d script = device.trajectory().Position(samples[n].time_s);
      if (n >= 100 && n < 200) {
        // NaN ticks: 0.1 and 0.2 are exactly 100 / 1000 and 200 / 1000 in doubles.
        EXPECT_TRUE(std::isnan(samples[n].position_m.y())) << n;
        if (hand == HandModel::kRigid) {
          EXPECT_EQ(samples[n].position_m.x(), script.x()) << n;
        }
      } else {
        EXPECT_TRUE(samples[n].position_m.allFinite()) << n;
        EXPECT_TRUE(samples[n].velocity_m_s.allFinite()) << n;
      }
      EXPECT_TRUE(samples[n].force_n.allFinite()) << n;
    }
    // First finite tick: the hand restarts on the script, at rest.
    EXPECT_EQ(samples[200].position_m, device.trajectory().Position(0.2));
    EXPECT_EQ(samples[200].velocity_m_s, Eigen::Vector3d::Zero());
    device.Stop();
    EXPECT_EQ(device.safety_counters().non_finite_states, 100);
  }
}

TEST(ScriptedDeviceTest, RecordingRoundTripsThroughCsv) {
  WallClient client = PressedWall();
  ScriptedDevice device(Press(), WithClock(ScriptedClock::kManual, HandModel::kSpring));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  while (device.Step(100) > 0) {
  }
  const auto samples = device.Recorded();
  const std::string path = TempPath(".csv");
  device.WriteCsv(path);

  // Positions, through the trajectory reader: at a sample's own time the interpolation weight
  // is exactly zero, so what comes back is the written number, which 17 digits make exact.
  const auto replay = LoadCsvTrajectory(path);
  EXPECT_EQ(replay->Duration(), samples.back().time_s);
  for (const ScriptedSample& s : samples) {
    ASSERT_EQ(replay->Position(s.time_s), s.position_m) << s.time_s;
  }

  // Forces, read back by hand.
  std::ifstream file(path);
  std::string line;
  ASSERT_TRUE(std::getline(file, line));
  EXPECT_EQ(line, "time_s,x_m,y_m,z_m,fx_n,fy_n,fz_n");
  std::size_t row = 0;
  while (std::getline(file, line)) {
    ASSERT_LT(row, samples.size());
    double values[7];
    const char* cursor = line.c_str();
    for (double& value : values) {
      char* end = nullptr;
      value = std::strtod(cursor, &end);
      cursor = *end == ',' ? end + 1 : end;
    }
    EXPECT_EQ(values[0], samples[row].time_s);
    EXPECT_EQ(Eigen::Vector3d(values[4], values[5], values[6]), samples[row].force_n) << row;
    ++row;
  }
  EXPECT_EQ(row, samples.size());
}

TEST(ScriptedDeviceTest, RecordingOffKeepsNothing) {
  ScriptedOptions options = WithClock(ScriptedClock::kManual);
  options.record = false;
  WallClient client = PressedWall();
  ScriptedDevice device(Press(), options);
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  EXPECT_EQ(device.Step(2000), 1001u);
  EXPECT_TRUE(device.Recorded().empty());
  const std::string path = TempPath(".csv");
  device.WriteCsv(path);
  std::ifstream file(path);
  std::string header;
  std::string extra;
  EXPECT_TRUE(std::getline(file, header));
  EXPECT_FALSE(std::getline(file, extra));
}

TEST(ScriptedDeviceTest, WriteCsvNamesAnUnwritablePath) {
  ScriptedDevice device(Press(), WithClock(ScriptedClock::kManual));
  const std::string path = TempPath("_missing_dir/run.csv");
  try {
    device.WriteCsv(path);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
}

/// A script whose Duration() is `duration`.
class FixedDuration final : public Trajectory {
 public:
  explicit FixedDuration(double duration) : duration_(duration) {}
  Eigen::Vector3d Position(double) const override { return Eigen::Vector3d::Zero(); }
  double Duration() const override { return duration_; }

 private:
  double duration_;
};

TEST(ScriptedDeviceTest, RejectsUnusableScriptsAndOptions) {
  EXPECT_THROW(ScriptedDevice(nullptr), std::invalid_argument);
  EXPECT_THROW(ScriptedDevice(std::make_unique<FixedDuration>(-1.0)), std::invalid_argument);
  EXPECT_THROW(
      ScriptedDevice(std::make_unique<FixedDuration>(std::numeric_limits<double>::infinity())),
      std::invalid_argument);
  ScriptedOptions options = WithClock(ScriptedClock::kManual, HandModel::kSpring);
  options.spring.stiffness_n_per_m = 1e6;  // beyond 4 m / h^2 = 1.8e5 N/m at 1 kHz
  EXPECT_THROW(ScriptedDevice(Press(), options), std::invalid_argument);
  options.hand = HandModel::kRigid;  // the spring is not used, so not checked
  EXPECT_NO_THROW(ScriptedDevice(Press(), options));
  options.safety.ramp_in_s = -1.0;
  EXPECT_THROW(ScriptedDevice(Press(), options), std::invalid_argument);
}

TEST(ScriptedDeviceTest, StartBeforeOpenIsOutOfOrder) {
  WallClient client = PressedWall();
  ScriptedDevice device(Press(), WithClock(ScriptedClock::kManual));
  EXPECT_EQ(device.Start(client), DeviceStatus::kInvalidState);
  EXPECT_EQ(device.Step(1), 0u);
}

}  // namespace
}  // namespace cosmems
