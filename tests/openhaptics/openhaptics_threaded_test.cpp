// The OpenHaptics backend on the fake's scheduler thread: it ticks and shuts down cleanly.
// How fast it ticks is for the benchmarks: nothing here depends on the machine's speed.
#include <chrono>
#include <thread>

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
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  device.Stop();
  const std::uint64_t ticks = client.ticks();
  EXPECT_GT(ticks, 0u);
  EXPECT_EQ(device.stats().ticks, ticks);
  EXPECT_TRUE(device.stats().paced);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(client.ticks(), ticks);  // no tick after Stop()
  EXPECT_EQ(hdFakeTickCount(), ticks);
  std::vector<double> latched(3);
  hdFakeLatchedForce(latched.data());
  EXPECT_EQ(latched, (std::vector<double>{0.0, 0.0, 0.0}));  // motors off
  device.Close();
  EXPECT_FALSE(device.servo_ended());
  EXPECT_EQ(device.last_error().code, 0u);
}

}  // namespace
}  // namespace cosmems
