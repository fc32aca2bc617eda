// The live script the viewer's mouse writes: each tick sees the newest target, whatever the time,
// on the manual clock tick by tick and on the paced clock from another thread.
#include "cosmems/scripted/live_trajectory.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "cosmems/scripted/scripted_device.hpp"

namespace cosmems {
namespace {

/// Remembers where the stylus was at the last tick.
class PositionClient final : public ServoClient {
 public:
  void Tick(const DeviceState& state, ForceCommand& command) noexcept override {
    last_ = state.position_m;
    ticks_.fetch_add(1, std::memory_order_release);
    command.force_n.setZero();
  }
  Eigen::Vector3d last() const { return last_; }
  long ticks() const { return ticks_.load(std::memory_order_acquire); }

 private:
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
  std::atomic<long> ticks_{0};
};

TEST(LiveTrajectoryTest, EachTickSeesTheNewestTarget) {
  auto live = std::make_unique<LiveTrajectory>(Eigen::Vector3d(0.0, 0.01, 0.0), 2.0);
  LiveTrajectory* hand = live.get();
  ScriptedOptions options;
  options.clock = ScriptedClock::kManual;
  ScriptedDevice device(std::move(live), options);
  PositionClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  ASSERT_EQ(device.Step(3), 3u);
  EXPECT_EQ(client.last(), Eigen::Vector3d(0.0, 0.01, 0.0));
  hand->MoveTo(Eigen::Vector3d(0.001, 0.0, 0.0));
  hand->MoveTo(Eigen::Vector3d(0.002, -0.005, 0.003));  // only the newest counts
  ASSERT_EQ(device.Step(1), 1u);
  EXPECT_EQ(client.last(), Eigen::Vector3d(0.002, -0.005, 0.003));
  ASSERT_EQ(device.Step(10), 10u);  // held while nothing new comes
  EXPECT_EQ(client.last(), Eigen::Vector3d(0.002, -0.005, 0.003));
  // The device ticks over [0, 2 s] at 1 kHz and then ends, as for any script.
  EXPECT_EQ(device.Step(5000), 2001u - 14u);
  EXPECT_TRUE(device.Done());
  // The rigid hand's velocity is the backward difference of the targets.
  const std::vector<ScriptedSample> samples = device.Recorded();
  EXPECT_TRUE(samples[3].velocity_m_s.isApprox(Eigen::Vector3d(2.0, -15.0, 3.0)));
  EXPECT_EQ(samples[4].velocity_m_s, Eigen::Vector3d::Zero());
}

TEST(LiveTrajectoryTest, APacedDeviceFollowsTargetsSetFromAnotherThread) {
  auto live = std::make_unique<LiveTrajectory>(Eigen::Vector3d::Zero());
  LiveTrajectory* hand = live.get();
  ScriptedOptions options;
  options.clock = ScriptedClock::kPaced;
  options.record = false;  // an open-ended session keeps no rows
  ScriptedDevice device(std::move(live), options);
  PositionClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  const Eigen::Vector3d target(0.01, 0.02, -0.03);
  std::thread mouse([hand, target] { hand->MoveTo(target); });
  mouse.join();
  const long seen = client.ticks();
  // The next ticks (1 ms apart) see it; wait for a few without timing anything.
  while (client.ticks() < seen + 5) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  device.Stop();
  EXPECT_EQ(client.last(), target);
  EXPECT_FALSE(device.Done());
  EXPECT_TRUE(device.Recorded().empty());
}

TEST(LiveTrajectoryTest, RefusesAStartOrDurationItCannotPlay) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(LiveTrajectory(Eigen::Vector3d(nan, 0.0, 0.0)), std::invalid_argument);
  EXPECT_THROW(LiveTrajectory(Eigen::Vector3d::Zero(), 0.0), std::invalid_argument);
  EXPECT_THROW(LiveTrajectory(Eigen::Vector3d::Zero(), std::numeric_limits<double>::infinity()),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
