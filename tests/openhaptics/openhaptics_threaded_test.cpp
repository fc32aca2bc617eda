// The OpenHaptics backend on the fake's scheduler thread: it ticks and shuts down cleanly.
// How fast it ticks is for the benchmarks: nothing here depends on the machine's speed.
#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "fake_hd_fixture.hpp"
#include "recording_client.hpp"

namespace cosmems {
namespace {

using OpenHapticsThreadedTest = FakeHdTest;

TEST_F(OpenHapticsThreadedTest, TicksOnTheSchedulerThreadAndStopsCleanly) {
  OpenHapticsDevice device;
  RecordingClient client(Eigen::Vector3d(0.2, 0.0, 0.0));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  // Counted in ticks, not in sleeps: a loaded machine ticks fewer of them in any time.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (client.ticks() < 300 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  device.Stop();
  const std::uint64_t ticks = client.ticks();
  ASSERT_GE(ticks, 300u);
  EXPECT_EQ(device.stats().ticks, ticks);
  EXPECT_TRUE(device.stats().paced);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(client.ticks(), ticks);  // no tick after Stop()
  // The stop's ramp ticks (0.2 N ramped in to at least 0.12 N by tick 300: two slew steps of
  // 0.1 N) run on the scheduler without the client; the scheduler may tick once more, empty,
  // before it stops.
  EXPECT_EQ(device.safety_counters().ramp_down_ticks, 2);
  EXPECT_GE(hdFakeTickCount(), ticks + 2);
  std::vector<double> latched(3);
  hdFakeLatchedForce(latched.data());
  EXPECT_EQ(latched, (std::vector<double>{0.0, 0.0, 0.0}));  // motors off
  device.Close();
  EXPECT_FALSE(device.servo_ended());
  EXPECT_EQ(device.last_error().code, 0u);
}

// Stopping with a force on does not drop it: the servo ticks bring it to zero along the slew
// limit, latch zero and turn the force output off, and the callback ends itself; only then is
// the scheduler stopped, and the device is released last (the HD API's shutdown order).
TEST_F(OpenHapticsThreadedTest, StopRampsTheForceDownThenShutsDownInTheSdksOrder) {
  OpenHapticsDevice device;
  RecordingClient client(Eigen::Vector3d(0.0, 0.8, 0.0));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  // Past the 0.5 s ramp-in, without assuming any speed of a loaded machine.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (client.ticks() < 700 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  device.Stop();
  device.Close();
  // The client's ticks, then the ramp's (the scheduler may tick once more, empty, before it
  // stops).
  const HDulong client_ticks = client.ticks();
  const auto ramp = static_cast<HDulong>(device.safety_counters().ramp_down_ticks);
  EXPECT_EQ(ramp, 8u);  // 0.8 N at 0.1 N a tick
  const HDulong end = client_ticks + ramp;
  ASSERT_GE(hdFakeTickCount(), end);
  ASSERT_LE(end, hdFakeForceLogSize());
  EXPECT_NEAR(LoggedForce(client_ticks - 1)[1], 0.8, 1e-12);  // the client's last tick
  for (HDulong k = client_ticks; k < end; ++k) {
    const double step = LoggedForce(k - 1)[1] - LoggedForce(k)[1];
    EXPECT_NEAR(step, 0.1, 1e-12) << "tick " << k;
  }
  EXPECT_EQ(LoggedForce(end - 1), (std::vector<double>{0.0, 0.0, 0.0}));
  const std::vector<std::string> calls = RecordedCalls();
  const auto start = std::find(calls.rbegin(), calls.rend(), "hdStartScheduler");
  ASSERT_NE(start, calls.rend());
  const std::vector<std::string> shutdown(start.base(), calls.end());
  EXPECT_EQ(shutdown,
            (std::vector<std::string>{"hdDisable", "hdStopScheduler", "hdDisableDevice"}));
  EXPECT_FALSE(device.servo_ended());
  EXPECT_EQ(device.last_error().code, 0u);
}

}  // namespace
}  // namespace cosmems
