// The OpenHaptics backend through the fake HD API, tick by tick: call order, specs, units and
// the safety layer's limit.
#include "cosmems/openhaptics/openhaptics_device.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "cosmems/haptics/safety_layer.hpp"
#include "extreme_values.hpp"
#include "fake_hd_fixture.hpp"
#include "recording_client.hpp"

namespace cosmems {
namespace {

class OpenHapticsDeviceTest : public FakeHdTest {
 protected:
  void SetUp() override {
    FakeHdTest::SetUp();
    hdFakeSetManualTicks(HD_TRUE);
  }
};

TEST_F(OpenHapticsDeviceTest, FollowsTheSdksSetUpAndShutdownOrder) {
  RecordingClient client;
  {
    OpenHapticsDevice device;
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
    EXPECT_TRUE(hdIsEnabled(HD_FORCE_OUTPUT));
    EXPECT_TRUE(hdIsEnabled(HD_MAX_FORCE_CLAMPING));
    hdFakeStep(3);
  }  // the destructor stops and closes
  const std::vector<std::string> wanted = {
      "hdInitDevice",           "hdEnable",         "hdEnable",        "hdSetSchedulerRate",
      "hdScheduleAsynchronous", "hdStartScheduler", "hdStopScheduler", "hdUnschedule",
      "hdDisableDevice"};
  std::vector<std::string> calls = RecordedCalls();
  calls.erase(std::remove_if(calls.begin(), calls.end(),
                             [&](const std::string& c) {
                               return std::find(wanted.begin(), wanted.end(), c) == wanted.end();
                             }),
              calls.end());
  EXPECT_EQ(calls, wanted);
  EXPECT_EQ(client.ticks(), 3u);
  EXPECT_TRUE(PopErrors().empty());
}

TEST_F(OpenHapticsDeviceTest, ReadsTheSpecsInSi) {
  OpenHapticsDevice device;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  const DeviceSpecs& s = device.specs();
  EXPECT_EQ(s.model, "PHANTOM Omni");
  EXPECT_EQ(s.max_force_n, 3.3);
  EXPECT_EQ(s.max_continuous_force_n, 0.88);
  // mm -> m and N/mm -> N/m are one multiplication each: a few ulps.
  EXPECT_NEAR(s.max_stiffness_n_per_m, 700.0, 1e-9);
  EXPECT_NEAR(s.max_damping_ns_per_m, 5.0, 1e-12);
  EXPECT_NEAR(s.workspace_min_m.x(), -0.080, 1e-15);
  EXPECT_NEAR(s.workspace_max_m.y(), 0.060, 1e-15);
  EXPECT_NEAR(s.workspace_max_m.z(), 0.035, 1e-15);
  EXPECT_EQ(s.nominal_rate_hz, 1000.0);
  EXPECT_EQ(s.buttons, 2);  // not reported by HD: from the built-in table
  // The default limit is the continuous force, which keeps the motors cool.
  EXPECT_EQ(device.force_limit_n(), 0.88);
}

TEST_F(OpenHapticsDeviceTest, StylusReachesTheClientInSi) {
  const HDdouble position_mm[3] = {12.5, -30.0, 7.0};
  hdFakeSetPosition(position_mm);
  hdFakeSetButtons(HD_DEVICE_BUTTON_1);
  OpenHapticsDevice device;
  RecordingClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(5);
  const DeviceState& s = client.last();
  EXPECT_EQ(s.tick, 4u);
  EXPECT_DOUBLE_EQ(s.time_s, 0.004);
  // One multiplication by 1e-3: within DOUBLE_EQ's 4 ulps.
  EXPECT_DOUBLE_EQ(s.position_m.x(), 0.0125);
  EXPECT_DOUBLE_EQ(s.position_m.y(), -0.030);
  EXPECT_DOUBLE_EQ(s.position_m.z(), 0.007);
  EXPECT_EQ(s.velocity_m_s, Eigen::Vector3d::Zero());
  EXPECT_EQ(s.orientation, Eigen::Matrix3d::Identity());
  EXPECT_EQ(s.buttons, 1u);
  EXPECT_FALSE(s.fault);
}

// 50 mm/s along z.
void Advance(HDdouble time_s, HDdouble position_mm[3], void*) {
  position_mm[0] = 0.0;
  position_mm[1] = 0.0;
  position_mm[2] = 50.0 * time_s;
}

TEST_F(OpenHapticsDeviceTest, VelocityReachesTheClientInSi) {
  hdFakeSetMotion(Advance, nullptr);
  OpenHapticsDevice device;
  RecordingClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(10);
  // A difference of positions times the rate, then 1e-3: rounding near 1e-15 m/s.
  EXPECT_NEAR(client.last().velocity_m_s.z(), 0.050, 1e-12);
}

TEST_F(OpenHapticsDeviceTest, ClientForceReachesTheDeviceInNewtons) {
  OpenHapticsDevice device(Immediate());
  RecordingClient client(Eigen::Vector3d(0.3, -0.2, 0.1));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(2);
  EXPECT_EQ(LoggedForce(1), (std::vector<double>{0.3, -0.2, 0.1}));
}

// The stylus jumps, every third tick, to an extreme value (test::ExtremeValues) in one
// coordinate [mm]: the driver's velocity, a difference times the rate, overflows.
void ExtremeMotion(HDdouble time_s, HDdouble position_mm[3], void*) {
  static const std::vector<double> extremes = test::ExtremeValues();
  const auto tick = static_cast<std::size_t>(std::llround(time_s * 1000.0));
  position_mm[0] = 10.0;
  position_mm[1] = -20.0 + time_s;
  position_mm[2] = 5.0;
  if (tick % 3 == 0) position_mm[tick / 3 % 3] = extremes[tick / 9 % extremes.size()];
}

/// Asks for a force of ordinary size with, every other tick, an extreme component.
class ExtremeClient final : public ServoClient {
 public:
  void Tick(const DeviceState& state, ForceCommand& command) noexcept override {
    command.force_n = Eigen::Vector3d(0.3, 0.5, -0.2);
    if (state.tick % 2 == 0) {
      command.force_n[static_cast<int>(state.tick / 2 % 3)] =
          extremes_[state.tick / 6 % extremes_.size()];
    }
  }

 private:
  std::vector<double> extremes_ = test::ExtremeValues();
};

// The same bounds on the OpenHaptics path: extreme stylus readings and extreme forces, tick
// after tick, never reach the motors as more than the limit, a non-finite force or a jump.
TEST_F(OpenHapticsDeviceTest, ExtremeReadingsAndForcesStayWithinTheBounds) {
  hdFakeSetMotion(ExtremeMotion, nullptr);
  OpenHapticsDevice device;
  ExtremeClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(20000);
  device.Stop();
  const double limit = device.force_limit_n();
  const double slew = SafetyLayer(SafetyOptions{}, device.specs()).slew_per_tick();
  std::vector<double> previous(3, 0.0);
  long breaches = 0;
  for (HDulong tick = 0; tick < std::min<HDulong>(20000, hdFakeForceLogSize()); ++tick) {
    const std::vector<double> f = LoggedForce(tick);
    const Eigen::Vector3d force(f[0], f[1], f[2]);
    const Eigen::Vector3d last(previous[0], previous[1], previous[2]);
    if (!(force.allFinite() && force.norm() <= limit * (1.0 + 1e-12) &&
          (force - last).norm() <= slew * (1.0 + 1e-12))) {
      ++breaches;
    }
    previous = f;
  }
  EXPECT_EQ(breaches, 0);
  const SafetyCounters counters = device.safety_counters();
  EXPECT_GT(counters.out_of_range_states + counters.non_finite_states, 0);
  EXPECT_GT(counters.clamped, 0);
  EXPECT_EQ(counters.output_guards, 0);
  EXPECT_GT(counters.max_force_n, 0.0);  // between the faults, forces were rendered
}

TEST_F(OpenHapticsDeviceTest, SafetyLayerHoldsTheForceUnderItsLimit) {
  OpenHapticsDevice device;  // default safety: ramp-in, slew limit, continuous-force limit
  RecordingClient client(Eigen::Vector3d(10.0, 0.0, 0.0));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(1000);
  device.Stop();
  double largest = 0.0;
  for (HDulong tick = 0; tick < hdFakeForceLogSize(); ++tick) {
    const std::vector<double> f = LoggedForce(tick);
    largest = std::max(largest, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]));
  }
  // The layer scales the force to the limit: the norm may exceed it by rounding only.
  EXPECT_LE(largest, device.force_limit_n() * (1.0 + 1e-12));
  EXPECT_GT(largest, 0.99 * device.force_limit_n());  // and the ramp has reached it
  EXPECT_GT(device.safety_counters().clamped, 0);
}

}  // namespace
}  // namespace cosmems
