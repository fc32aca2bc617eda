// The OpenHaptics backend when the device fails: force and scheduler errors in the loop,
// calibration, and a device that is busy or absent.
#include <algorithm>

#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "fake_hd_fixture.hpp"
#include "recording_client.hpp"

namespace cosmems {
namespace {

class OpenHapticsFaultTest : public FakeHdTest {
 protected:
  void SetUp() override {
    FakeHdTest::SetUp();
    hdFakeSetManualTicks(HD_TRUE);
  }
};

long Count(const std::string& call) {
  const std::vector<std::string> calls = RecordedCalls();
  return std::count(calls.begin(), calls.end(), call);
}

TEST_F(OpenHapticsFaultTest, ForceErrorZeroesTheForceThenRampsItIn) {
  OpenHapticsOptions options;
  options.safety.slew_limit_n_per_s = 1e6;  // no slew limit in the way: steps show the ramp
  options.safety.ramp_in_s = 0.5;           // 500 ticks at 1 kHz
  OpenHapticsDevice device(options);
  RecordingClient client(Eigen::Vector3d(0.5, 0.0, 0.0));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  constexpr HDulong kFault = 600;  // after the first ramp-in
  hdFakeInjectError(HD_WARM_MOTORS, kFault);
  hdFakeStep(1200);
  device.Stop();
  EXPECT_EQ(LoggedForce(kFault - 1)[0], 0.5);
  EXPECT_EQ(LoggedForce(kFault)[0], 0.0);      // the device refused the tick's force
  EXPECT_EQ(LoggedForce(kFault + 1)[0], 0.0);  // the next tick is a fault: the layer drops it
  // Then the ramp starts over: 1/500 of the force per tick, rising until it is whole again.
  // Each value is a product of a few doubles: 1e-12 N is far beyond their rounding.
  EXPECT_NEAR(LoggedForce(kFault + 2)[0], 0.5 / 500.0, 1e-12);
  for (HDulong tick = kFault + 2; tick < kFault + 501; ++tick) {
    EXPECT_GE(LoggedForce(tick + 1)[0], LoggedForce(tick)[0]) << tick;
  }
  EXPECT_NEAR(LoggedForce(1199)[0], 0.5, 1e-12);
  EXPECT_FALSE(device.servo_ended());
  EXPECT_EQ(device.last_error().code, static_cast<unsigned>(HD_WARM_MOTORS));
  EXPECT_EQ(device.safety_counters().device_faults, 1);
}

TEST_F(OpenHapticsFaultTest, SchedulerErrorEndsTheLoopAndIsReported) {
  OpenHapticsDevice device;
  RecordingClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeInjectError(HD_COMM_ERROR, 10);
  hdFakeStep(20);
  EXPECT_EQ(client.ticks(), 11u);  // ticks 0 to 10, then the callback is gone
  EXPECT_TRUE(device.servo_ended());
  const OpenHapticsError error = device.last_error();
  EXPECT_EQ(error.code, static_cast<unsigned>(HD_COMM_ERROR));
  EXPECT_EQ(error.description, hdGetErrorString(HD_COMM_ERROR));
  device.Stop();
  // The callback had removed itself: nothing left to unschedule, and no error from trying.
  EXPECT_EQ(Count("hdUnschedule"), 0);
  EXPECT_EQ(device.last_error().code, static_cast<unsigned>(HD_COMM_ERROR));
}

// A failed link loses the tick's command and the amplifiers keep the last force (the fake models
// that): the failing tick itself must turn the force output off, since no later tick will come
// to ramp it down and Stop() may be far away (or never called, by a viewer that did not look).
TEST_F(OpenHapticsFaultTest, ASchedulerErrorTurnsTheForceOffOnTheFailingTick) {
  OpenHapticsDevice device(Immediate());
  RecordingClient client(Eigen::Vector3d(0.5, 0.0, 0.0));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  constexpr HDulong kFault = 10;
  hdFakeInjectError(HD_COMM_ERROR, kFault);
  hdFakeStep(30);  // the scheduler keeps ticking, with the callback gone
  ASSERT_TRUE(device.servo_ended());
  EXPECT_EQ(LoggedForce(kFault - 1)[0], 0.5);
  for (HDulong tick = kFault; tick < 30; ++tick) {
    EXPECT_EQ(LoggedForce(tick), (std::vector<double>{0.0, 0.0, 0.0})) << "tick " << tick;
  }
  EXPECT_EQ(hdIsEnabled(HD_FORCE_OUTPUT), HD_FALSE);
  device.Stop();
  EXPECT_EQ(device.last_error().code, static_cast<unsigned>(HD_COMM_ERROR));
}

// An uncalibrated device does not know where the stylus is: the client is not asked, the motors
// stay off and the force zero; once the calibration is done (here an update the loop makes when
// the stylus is in the inkwell), the motors come on and the force ramps in.
TEST_F(OpenHapticsFaultTest, NoForceUntilTheDeviceIsCalibrated) {
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_MANUAL_INPUT);
  OpenHapticsDevice device(Immediate(0.01));  // a ramp-in of 10 ticks
  RecordingClient client(Eigen::Vector3d(0.5, 0.0, 0.0));
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(20);
  EXPECT_EQ(client.ticks(), 0u);
  for (HDulong tick = 0; tick < 20; ++tick) {
    EXPECT_EQ(LoggedForce(tick)[0], 0.0) << "tick " << tick;
  }
  EXPECT_EQ(hdIsEnabled(HD_FORCE_OUTPUT), HD_FALSE);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kNeedsManualInput);
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_UPDATE);  // the stylus went into the inkwell
  hdFakeStep(20);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kOk);
  EXPECT_EQ(hdIsEnabled(HD_FORCE_OUTPUT), HD_TRUE);
  EXPECT_NEAR(LoggedForce(20)[0], 0.05, 1e-12);  // a tenth of the force: the ramp's first tick
  EXPECT_NEAR(LoggedForce(39)[0], 0.5, 1e-12);
  device.Stop();  // the figures are complete from here
  EXPECT_EQ(device.safety_counters().uncalibrated_ticks, 20);
}

// The HD API cannot tell a live session of this process from a handle a crash left behind; the
// process-wide claim can: a second Open() of the device is refused, and the first session keeps
// its device, its scheduler and its force.
TEST_F(OpenHapticsFaultTest, ASecondSessionDoesNotTakeOverALiveDevice) {
  OpenHapticsDevice first(Immediate());
  RecordingClient client(Eigen::Vector3d(0.5, 0.0, 0.0));
  ASSERT_EQ(first.Open(), DeviceStatus::kOk);
  ASSERT_EQ(first.Start(client), DeviceStatus::kOk);
  hdFakeStep(5);
  OpenHapticsDevice second;
  EXPECT_EQ(second.Open(), DeviceStatus::kAlreadyInUse);
  EXPECT_EQ(second.last_error().code, static_cast<unsigned>(HD_DEVICE_ALREADY_INITIATED));
  EXPECT_EQ(Count("hdDisableDevice"), 0);
  EXPECT_EQ(Count("hdInitDevice"), 1);
  hdFakeStep(5);
  EXPECT_EQ(client.ticks(), 10u);
  EXPECT_EQ(LoggedForce(9)[0], 0.5);
  first.Stop();
  first.Close();
  EXPECT_EQ(second.Open(), DeviceStatus::kOk);  // released with the first session
}

TEST_F(OpenHapticsFaultTest, CalibrationStatesMapAndUpdatableOnesAreUpdated) {
  OpenHapticsDevice device;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kOk);
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_MANUAL_INPUT);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kNeedsManualInput);
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_UPDATE);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kOk);  // updated with the inkwell style
  EXPECT_EQ(Count("hdUpdateCalibration"), 1);

  HDFakeSpecs no_styles;
  hdFakeDefaultSpecs(&no_styles);
  no_styles.calibration_styles = 0;
  hdFakeSetSpecs(&no_styles);
  OpenHapticsDevice other;
  device.Close();
  ASSERT_EQ(other.Open(), DeviceStatus::kOk);
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_UPDATE);
  EXPECT_EQ(other.Calibration(), CalibrationStatus::kNeedsUpdate);  // no style to update with
}

TEST_F(OpenHapticsFaultTest, RunningLoopFinishesTheCalibration) {
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_MANUAL_INPUT);
  OpenHapticsDevice device;
  RecordingClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(client), DeviceStatus::kOk);
  hdFakeStep(1);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kNeedsManualInput);
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_UPDATE);  // the stylus went into the inkwell
  hdFakeStep(1);
  EXPECT_EQ(device.Calibration(), CalibrationStatus::kOk);
}

TEST_F(OpenHapticsFaultTest, RetriesAStaleInitialisation) {
  hdFakeFailInit(HD_DEVICE_ALREADY_INITIATED, 3);
  OpenHapticsDevice device;
  EXPECT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(Count("hdInitDevice"), 4);
}

TEST_F(OpenHapticsFaultTest, ReleasesADeviceThisProcessLeftInitialised) {
  hdInitDevice(HD_DEFAULT_DEVICE);  // as a crashed earlier user in this process would
  OpenHapticsDevice device;
  EXPECT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(Count("hdDisableDevice"), 1);
}

TEST_F(OpenHapticsFaultTest, DeviceHeldElsewhereIsInUse) {
  hdFakeFailInit(HD_DEVICE_ALREADY_INITIATED, 1000);
  OpenHapticsDevice device;
  EXPECT_EQ(device.Open(), DeviceStatus::kAlreadyInUse);
  EXPECT_EQ(Count("hdInitDevice"), 11);  // the first try and ten more
  EXPECT_EQ(device.last_error().code, static_cast<unsigned>(HD_DEVICE_ALREADY_INITIATED));
}

TEST_F(OpenHapticsFaultTest, AbsentDeviceIsNotFound) {
  hdFakeSetDevicePresent(HD_FALSE);
  OpenHapticsDevice device;
  EXPECT_EQ(device.Open(), DeviceStatus::kNotFound);
  EXPECT_FALSE(device.is_open());
  EXPECT_EQ(device.last_error().code, static_cast<unsigned>(HD_DEVICE_FAULT));
}

TEST_F(OpenHapticsFaultTest, UnsupportedRateFailsTheStart) {
  OpenHapticsOptions options;
  options.scheduler_rate_hz = 1600;  // FireWire only; the fake is a PCI-style device
  OpenHapticsDevice device(options);
  RecordingClient client;
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(device.Start(client), DeviceStatus::kCommError);
  EXPECT_FALSE(device.is_running());
  EXPECT_EQ(device.last_error().code, static_cast<unsigned>(HD_INVALID_VALUE));
}

}  // namespace
}  // namespace cosmems
