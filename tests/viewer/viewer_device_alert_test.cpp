// The viewer's session when the device fails under the hand: a scheduler error on the fake HD
// API's device, whose manual ticks this test drives. The display must hear of it at once, and
// the session must stop (motors off, physics joined) without waiting for the window to close.
#include <HD/hd.h>
#include <HD/hd_fake.h>
#include <gtest/gtest.h>

#include "cosmems/scene/scene_loader.hpp"
#include "viewer_session.hpp"

namespace cosmems::viewer {
namespace {

class ViewerDeviceAlertTest : public ::testing::Test {
 protected:
  void SetUp() override {
    hdFakeReset();
    hdFakeSetManualTicks(HD_TRUE);
  }
  void TearDown() override { hdFakeReset(); }

  static Scene OmniScene() {
    return LoadScene("cantilever-haptic", {{"device.backend", "\"openhaptics\""}});
  }
};

TEST_F(ViewerDeviceAlertTest, AFailedServoLoopIsShownAndStopsTheSession) {
  std::unique_ptr<ViewerSession> session =
      ViewerSession::Start(OmniScene(), Input::kOmni, HapticPhysicsOptions{});
  hdFakeStep(5);
  EXPECT_EQ(session->DeviceAlert(), "");
  EXPECT_TRUE(session->opened().device->is_running());
  hdFakeInjectError(HD_COMM_ERROR, 7);
  hdFakeStep(5);
  const std::string alert = session->DeviceAlert();
  EXPECT_NE(alert.find("stopped the servo loop"), std::string::npos) << alert;
  EXPECT_NE(alert.find("motors are off"), std::string::npos) << alert;
  EXPECT_FALSE(session->opened().device->is_running());
  EXPECT_EQ(hdIsEnabled(HD_FORCE_OUTPUT), HD_FALSE);
  EXPECT_EQ(session->DeviceAlert(), alert);  // it stays on the panel
}

TEST_F(ViewerDeviceAlertTest, AnUncalibratedDeviceIsShownUntilItIsCalibrated) {
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_MANUAL_INPUT);
  std::unique_ptr<ViewerSession> session =
      ViewerSession::Start(OmniScene(), Input::kOmni, HapticPhysicsOptions{});
  hdFakeStep(3);
  EXPECT_NE(session->DeviceAlert().find("forces are off until the device is calibrated"),
            std::string::npos)
      << session->DeviceAlert();
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_UPDATE);  // the stylus went into the inkwell
  hdFakeStep(3);
  EXPECT_EQ(session->DeviceAlert(), "");
  session->Stop();
}

}  // namespace
}  // namespace cosmems::viewer
