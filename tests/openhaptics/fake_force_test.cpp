// The fake HD device's force output: latched at the frame's end, gated, clamped, limited.
#include <cmath>

#include "fake_hd_fixture.hpp"

namespace cosmems {
namespace {

// Commands `force` in one frame each tick and keeps what the device reported.
struct ForceScript {
  HDdouble force[3] = {};
  HDdouble latched_before_end[3] = {};
  std::vector<HDerror> errors;
};

HDCallbackCode HDCALLBACK CommandForce(void* user) {
  auto* s = static_cast<ForceScript*>(user);
  const HHD device = hdGetCurrentDevice();
  hdBeginFrame(device);
  hdSetDoublev(HD_CURRENT_FORCE, s->force);
  hdFakeLatchedForce(s->latched_before_end);
  hdEndFrame(device);
  s->errors = PopErrors();
  return HD_CALLBACK_CONTINUE;
}

class FakeForceTest : public FakeHdTest {
 protected:
  void SetUp() override {
    FakeHdTest::SetUp();
    hdInitDevice(HD_DEFAULT_DEVICE);
    hdScheduleAsynchronous(CommandForce, &script_, HD_MAX_SCHEDULER_PRIORITY);
    hdFakeSetManualTicks(HD_TRUE);
    hdStartScheduler();
  }
  std::vector<double> Tick(double fx, double fy, double fz) {
    script_.force[0] = fx;
    script_.force[1] = fy;
    script_.force[2] = fz;
    hdFakeStep(1);
    std::vector<double> latched(3);
    hdFakeLatchedForce(latched.data());
    return latched;
  }
  ForceScript script_;
};

TEST_F(FakeForceTest, LatchedAtTheEndOfTheFrame) {
  EXPECT_EQ(Tick(0.5, -0.25, 0.125), (std::vector<double>{0.5, -0.25, 0.125}));
  EXPECT_EQ(Tick(0.1, 0.0, 0.0), (std::vector<double>{0.1, 0.0, 0.0}));
  EXPECT_EQ(script_.latched_before_end[0], 0.5);  // the previous tick's until hdEndFrame
  EXPECT_EQ(LoggedForce(0), (std::vector<double>{0.5, -0.25, 0.125}));
  EXPECT_EQ(hdFakeForceLogSize(), 2u);
  EXPECT_TRUE(script_.errors.empty());
}

TEST_F(FakeForceTest, NothingWithoutForceOutputOrScheduler) {
  hdDisable(HD_FORCE_OUTPUT);
  EXPECT_EQ(Tick(1.0, 0.0, 0.0), (std::vector<double>{0.0, 0.0, 0.0}));
  hdEnable(HD_FORCE_OUTPUT);
  EXPECT_EQ(Tick(1.0, 0.0, 0.0), (std::vector<double>{1.0, 0.0, 0.0}));
  hdStopScheduler();
  std::vector<double> latched(3);
  hdFakeLatchedForce(latched.data());
  EXPECT_EQ(latched, (std::vector<double>{0.0, 0.0, 0.0}));
}

TEST_F(FakeForceTest, ClampingScalesToThePeakForce) {
  hdEnable(HD_MAX_FORCE_CLAMPING);
  const std::vector<double> f = Tick(3.0, 4.0, 0.0);  // 5 N
  // Scaled by 3.3 / 5 in doubles: a few ulps of 3.3 N.
  EXPECT_NEAR(f[0], 3.0 * 3.3 / 5.0, 1e-12);
  EXPECT_NEAR(f[1], 4.0 * 3.3 / 5.0, 1e-12);
  EXPECT_TRUE(script_.errors.empty());
}

TEST_F(FakeForceTest, SoftwareLimitRefusesTooLargeAForce) {
  EXPECT_EQ(Tick(5.0, 0.0, 0.0), (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(script_.errors, std::vector<HDerror>{HD_EXCEEDED_MAX_FORCE});
  hdDisable(HD_SOFTWARE_FORCE_LIMIT);
  EXPECT_EQ(Tick(5.0, 0.0, 0.0), (std::vector<double>{5.0, 0.0, 0.0}));
  EXPECT_TRUE(script_.errors.empty());
}

TEST_F(FakeForceTest, AForceErrorRefusesItsTicksForce) {
  hdFakeInjectError(HD_WARM_MOTORS, 1);
  EXPECT_EQ(Tick(1.0, 0.0, 0.0)[0], 1.0);
  EXPECT_EQ(Tick(1.0, 0.0, 0.0)[0], 0.0);
  EXPECT_EQ(script_.errors, std::vector<HDerror>{HD_WARM_MOTORS});
  EXPECT_EQ(Tick(1.0, 0.0, 0.0)[0], 1.0);
}

// A failed link loses the command, not the force: the amplifiers hold the last one until the
// force output is turned off, which is why a servo loop must turn it off when its link fails.
TEST_F(FakeForceTest, ALinkErrorKeepsTheLastForceUntilForceOutputIsOff) {
  hdFakeInjectError(HD_COMM_ERROR, 1);
  EXPECT_EQ(Tick(1.0, 0.0, 0.0)[0], 1.0);
  EXPECT_EQ(Tick(2.0, 0.0, 0.0)[0], 1.0);
  EXPECT_EQ(script_.errors, std::vector<HDerror>{HD_COMM_ERROR});
  std::vector<double> latched(3);
  hdFakeLatchedForce(latched.data());
  EXPECT_EQ(latched[0], 1.0);
  hdDisable(HD_FORCE_OUTPUT);
  hdFakeLatchedForce(latched.data());
  EXPECT_EQ(latched, (std::vector<double>{0.0, 0.0, 0.0}));
}

}  // namespace
}  // namespace cosmems
