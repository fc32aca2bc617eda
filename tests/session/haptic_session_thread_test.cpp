// A haptic session as a program runs it, across its threads: the device's servo thread, the
// physics thread, a display thread reading frames, figures and alerts and asking for resets, and
// the thread that starts and stops it. Built under ThreadSanitizer with the session, the device
// layer and both backends instrumented (ThreadSanitizer.HapticSession); nothing here depends on
// how fast the machine is.
#include <HD/hd.h>
#include <HD/hd_fake.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>

#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "cosmems/session/haptic_session.hpp"

namespace cosmems {
namespace {

// Waits, in wall time with a generous limit, until `done` holds.
template <typename Done>
bool WaitFor(Done done) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!done()) {
    if (std::chrono::steady_clock::now() > give_up) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return true;
}

// What a display does at 30 Hz, as fast as it can: frames, figures, alerts, a reset.
class Display {
 public:
  explicit Display(HapticSession& session)
      : thread_([this, &session] {
          while (!stop_.load()) {
            if (session.loop().UpdateFrame()) frames_.fetch_add(1);
            (void)session.loop().frame().probe_m;
            (void)session.device().stats();
            (void)session.device().safety_counters();
            if (!session.DeviceAlert().empty()) alert_seen_ = true;
            if (frames_.load() == 5) session.loop().RequestReset();
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
        }) {}
  ~Display() { Join(); }
  void Join() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  long frames() const { return frames_.load(); }
  bool alert_seen() const { return alert_seen_.load(); }

 private:
  std::atomic<bool> stop_{false};
  std::atomic<long> frames_{0};
  std::atomic<bool> alert_seen_{false};
  std::thread thread_;
};

class HapticSessionThreadTest : public ::testing::Test {
 protected:
  void SetUp() override { hdFakeReset(); }
  void TearDown() override { hdFakeReset(); }
};

TEST_F(HapticSessionThreadTest, APacedScriptWithADisplayStartsAndStops) {
  const Scene scene = LoadScene("cantilever-haptic");
  HapticSession session(scene, OpenDevice(scene));
  session.Start();
  Display display(session);
  ASSERT_TRUE(WaitFor([&] { return display.frames() >= 10; }));
  session.Stop();
  display.Join();
  EXPECT_GT(session.device().stats().ticks, 0u);
  EXPECT_FALSE(display.alert_seen());
}

// The fake device's scheduler thread fails under the session: the display hears of it while the
// servo thread ends and turns the motors off, and the stop afterwards is clean.
TEST_F(HapticSessionThreadTest, AFailingDeviceIsSeenFromTheDisplayThread) {
  const Scene scene = LoadScene("cantilever-haptic", {{"device.backend", "\"openhaptics\""}});
  HapticSession session(scene, OpenDevice(scene));
  session.Start();
  Display display(session);
  ASSERT_TRUE(WaitFor([] { return hdFakeTickCount() >= 20; }));
  hdFakeInjectError(HD_COMM_ERROR, hdFakeTickCount() + 5);
  ASSERT_TRUE(WaitFor([&] { return display.alert_seen(); }));
  display.Join();
  EXPECT_FALSE(session.ServoFault().empty());
  session.Stop();
  std::vector<double> latched(3);
  hdFakeLatchedForce(latched.data());
  EXPECT_EQ(latched, (std::vector<double>{0.0, 0.0, 0.0}));
}

// Two programs' threads open the one device at once (a sweep's workers did): exactly one gets it;
// the other is refused by name, and the one that has it runs undisturbed.
TEST_F(HapticSessionThreadTest, OnlyOneOfTwoThreadsGetsTheDevice) {
  const Scene scene = LoadScene("cantilever-haptic", {{"device.backend", "\"openhaptics\""}});
  std::atomic<int> opened{0}, refused{0};
  std::optional<OpenedDevice> kept[2];
  auto open = [&](int i) {
    try {
      kept[i].emplace(OpenDevice(scene));
      opened.fetch_add(1);
    } catch (const std::runtime_error& e) {
      if (std::string(e.what()).find("device.backend") != std::string::npos) refused.fetch_add(1);
    }
  };
  std::thread first(open, 0), second(open, 1);
  first.join();
  second.join();
  EXPECT_EQ(opened.load(), 1);
  EXPECT_EQ(refused.load(), 1);
  OpenedDevice& holder = kept[0] ? *kept[0] : *kept[1];
  HapticSession session(scene, std::move(holder));
  session.Start();
  ASSERT_TRUE(WaitFor([] { return hdFakeTickCount() >= 50; }));
  EXPECT_TRUE(session.ServoFault().empty());
  session.Stop();
}

}  // namespace
}  // namespace cosmems
