// The fake HD device: initialisation, frames, the error stack, units and calibration.
#include <cstring>

#include "fake_hd_fixture.hpp"

namespace cosmems {
namespace {

using FakeDeviceTest = FakeHdTest;

TEST_F(FakeDeviceTest, InitialisesOnceAndReportsWhyNot) {
  const HHD device = hdInitDevice(HD_DEFAULT_DEVICE);
  EXPECT_NE(device, static_cast<HHD>(HD_INVALID_HANDLE));
  EXPECT_EQ(hdGetCurrentDevice(), device);
  EXPECT_EQ(hdInitDevice("Default Device"), static_cast<HHD>(HD_INVALID_HANDLE));
  EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_DEVICE_ALREADY_INITIATED});
  hdDisableDevice(device);
  EXPECT_EQ(hdGetCurrentDevice(), static_cast<HHD>(HD_INVALID_HANDLE));

  hdFakeFailInit(HD_DEVICE_ALREADY_INITIATED, 1);
  EXPECT_EQ(hdInitDevice(HD_DEFAULT_DEVICE), static_cast<HHD>(HD_INVALID_HANDLE));
  EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_DEVICE_ALREADY_INITIATED});
  EXPECT_EQ(hdInitDevice(HD_DEFAULT_DEVICE), device);  // the injected failures are used up
  hdDisableDevice(device);

  hdFakeSetDevicePresent(HD_FALSE);
  EXPECT_EQ(hdInitDevice(HD_DEFAULT_DEVICE), static_cast<HHD>(HD_INVALID_HANDLE));
  EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_DEVICE_FAULT});
}

TEST_F(FakeDeviceTest, ErrorStackPopsNewestFirstAndNamesTheDevice) {
  const HHD device = hdInitDevice(HD_DEFAULT_DEVICE);
  HDdouble value = 0.0;
  hdGetDoublev(0x9999, &value);  // no such parameter
  hdSetSchedulerRate(3);
  hdUnschedule(42);
  const HDErrorInfo newest = hdGetError();
  EXPECT_EQ(newest.errorCode, static_cast<HDerror>(HD_INVALID_OPERATION));
  EXPECT_EQ(newest.hHD, device);
  EXPECT_EQ(hdGetError().errorCode, static_cast<HDerror>(HD_INVALID_VALUE));
  EXPECT_EQ(hdGetError().errorCode, static_cast<HDerror>(HD_INVALID_ENUM));
  EXPECT_FALSE(HD_DEVICE_ERROR(hdGetError()));
  EXPECT_STRNE(hdGetErrorString(HD_COMM_ERROR), hdGetErrorString(HD_SUCCESS));
}

struct FrameScript {
  int begins = 1;  // frames begun in a row (nested)
  int ends = 1;
  bool second_frame = false;
  std::vector<HDerror> errors;
};

HDCallbackCode HDCALLBACK RunFrames(void* user) {
  auto* s = static_cast<FrameScript*>(user);
  const HHD device = hdGetCurrentDevice();
  for (int i = 0; i < s->begins; ++i) hdBeginFrame(device);
  for (int i = 0; i < s->ends; ++i) hdEndFrame(device);
  if (s->second_frame) {
    hdBeginFrame(device);
    hdEndFrame(device);
  }
  s->errors = PopErrors();
  return HD_CALLBACK_CONTINUE;
}

class FakeFrameTest : public FakeHdTest {
 protected:
  std::vector<HDerror> RunOneTick(FrameScript script) {
    hdInitDevice(HD_DEFAULT_DEVICE);
    hdScheduleAsynchronous(RunFrames, &script, HD_DEFAULT_SCHEDULER_PRIORITY);
    hdFakeSetManualTicks(HD_TRUE);
    hdStartScheduler();
    hdFakeStep(1);
    return script.errors;
  }
};

TEST_F(FakeFrameTest, OneFramePerTick) {
  FrameScript twice;
  twice.second_frame = true;
  // The second begin fails; its end then has no frame to end.
  EXPECT_EQ(RunOneTick(twice), (std::vector<HDerror>{HD_ILLEGAL_END, HD_ILLEGAL_BEGIN}));
}

TEST_F(FakeFrameTest, NestedFramesShareOneFrame) {
  FrameScript nested;
  nested.begins = 3;
  nested.ends = 3;
  EXPECT_TRUE(RunOneTick(nested).empty());
}

TEST_F(FakeFrameTest, EndWithoutBeginIsIllegal) {
  FrameScript unbalanced;
  unbalanced.begins = 0;
  EXPECT_EQ(RunOneTick(unbalanced), std::vector<HDerror>{HD_ILLEGAL_END});
}

TEST_F(FakeFrameTest, OutsideTheSchedulerFramesAreNotLimited) {
  const HHD device = hdInitDevice(HD_DEFAULT_DEVICE);
  for (int i = 0; i < 3; ++i) {
    hdBeginFrame(device);
    hdEndFrame(device);
  }
  EXPECT_TRUE(PopErrors().empty());
}

// 100 mm/s along x from x = 10 mm.
void Sweep(HDdouble time_s, HDdouble position_mm[3], void*) {
  position_mm[0] = 10.0 + 100.0 * time_s;
  position_mm[1] = -20.0;
  position_mm[2] = 5.0;
}

struct Reading {
  HDdouble position[3] = {};
  HDdouble velocity[3] = {};
  HDdouble transform[16] = {};
  HDint buttons = 0;
};

HDCallbackCode HDCALLBACK ReadStylus(void* user) {
  auto* r = static_cast<Reading*>(user);
  hdBeginFrame(hdGetCurrentDevice());
  hdGetDoublev(HD_CURRENT_POSITION, r->position);
  hdGetDoublev(HD_CURRENT_VELOCITY, r->velocity);
  hdGetDoublev(HD_CURRENT_TRANSFORM, r->transform);
  hdGetIntegerv(HD_CURRENT_BUTTONS, &r->buttons);
  hdEndFrame(hdGetCurrentDevice());
  return HD_CALLBACK_CONTINUE;
}

TEST_F(FakeDeviceTest, StylusInMillimetres) {
  hdInitDevice(HD_DEFAULT_DEVICE);
  hdFakeSetMotion(Sweep, nullptr);
  hdFakeSetButtons(HD_DEVICE_BUTTON_2);
  Reading r;
  hdScheduleAsynchronous(ReadStylus, &r, HD_DEFAULT_SCHEDULER_PRIORITY);
  hdFakeSetManualTicks(HD_TRUE);
  hdStartScheduler();
  hdFakeStep(11);  // the last tick is tick 10, at 10 ms
  // 10 + 100 t and the difference of two positions times the rate, in doubles: their rounding
  // error is about 1e-14 mm; 1e-9 mm bounds it with room to spare.
  EXPECT_NEAR(r.position[0], 11.0, 1e-9);
  EXPECT_NEAR(r.position[1], -20.0, 1e-9);
  EXPECT_NEAR(r.velocity[0], 100.0, 1e-9);
  EXPECT_NEAR(r.velocity[1], 0.0, 1e-9);
  EXPECT_EQ(r.transform[12], r.position[0]);  // column-major: translation in the last column
  EXPECT_EQ(r.transform[13], r.position[1]);
  EXPECT_EQ(r.transform[0], 1.0);
  EXPECT_EQ(r.buttons, HD_DEVICE_BUTTON_2);
  EXPECT_TRUE(PopErrors().empty());
}

TEST_F(FakeDeviceTest, ReportsTheOmniInTheApisUnits) {
  hdInitDevice(HD_DEFAULT_DEVICE);
  EXPECT_STREQ(hdGetString(HD_DEVICE_MODEL_TYPE), "PHANTOM Omni");
  HDdouble value = 0.0;
  hdGetDoublev(HD_NOMINAL_MAX_FORCE, &value);
  EXPECT_EQ(value, 3.3);
  hdGetDoublev(HD_NOMINAL_MAX_CONTINUOUS_FORCE, &value);
  EXPECT_EQ(value, 0.88);
  hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &value);
  EXPECT_EQ(value, 0.7);  // N/mm
  hdGetDoublev(HD_NOMINAL_MAX_DAMPING, &value);
  EXPECT_EQ(value, 0.005);  // N s/mm
  HDdouble box[6] = {};
  hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, box);
  EXPECT_EQ(box[0], -80.0);
  EXPECT_EQ(box[4], 60.0);
  EXPECT_EQ(box[5], 35.0);
  HDint styles = 0;
  hdGetIntegerv(HD_CALIBRATION_STYLE, &styles);
  EXPECT_EQ(styles, HD_CALIBRATION_INKWELL);
  HDfloat as_float = 0.0f;
  hdGetFloatv(HD_NOMINAL_MAX_FORCE, &as_float);
  EXPECT_EQ(as_float, 3.3f);
  EXPECT_TRUE(PopErrors().empty());

  EXPECT_EQ(hdGetString(HD_NOMINAL_MAX_FORCE), nullptr);
  hdGetDoublev(HD_DEVICE_MODEL_TYPE, &value);
  EXPECT_EQ(PopErrors(), (std::vector<HDerror>{HD_INVALID_INPUT_TYPE, HD_INVALID_INPUT_TYPE}));
}

TEST_F(FakeDeviceTest, SpecsComeFromTheHook) {
  HDFakeSpecs specs;
  hdFakeDefaultSpecs(&specs);
  std::strcpy(specs.model, "Touch");
  specs.max_stiffness_n_per_mm = 0.4;
  hdFakeSetSpecs(&specs);
  hdInitDevice(HD_DEFAULT_DEVICE);
  EXPECT_STREQ(hdGetString(HD_DEVICE_MODEL_TYPE), "Touch");
  HDdouble stiffness = 0.0;
  hdGetDoublev(HD_NOMINAL_MAX_STIFFNESS, &stiffness);
  EXPECT_EQ(stiffness, 0.4);
}

TEST_F(FakeDeviceTest, CalibrationStatesAndStyles) {
  hdInitDevice(HD_DEFAULT_DEVICE);
  EXPECT_EQ(hdCheckCalibration(), static_cast<HDenum>(HD_CALIBRATION_OK));
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_MANUAL_INPUT);
  hdUpdateCalibration(HD_CALIBRATION_INKWELL);
  EXPECT_EQ(hdCheckCalibration(), static_cast<HDenum>(HD_CALIBRATION_NEEDS_MANUAL_INPUT));
  hdFakeSetCalibration(HD_CALIBRATION_NEEDS_UPDATE);
  hdUpdateCalibration(HD_CALIBRATION_AUTO);  // the Omni has no automatic calibration
  EXPECT_EQ(PopErrors(), std::vector<HDerror>{HD_INVALID_VALUE});
  EXPECT_EQ(hdCheckCalibration(), static_cast<HDenum>(HD_CALIBRATION_NEEDS_UPDATE));
  hdUpdateCalibration(HD_CALIBRATION_INKWELL);
  EXPECT_EQ(hdCheckCalibration(), static_cast<HDenum>(HD_CALIBRATION_OK));
  EXPECT_EQ(hdCheckCalibrationStyle(), static_cast<HDenum>(HD_CALIBRATION_INKWELL));
  EXPECT_TRUE(PopErrors().empty());
}

}  // namespace
}  // namespace cosmems
