// Calibration of the fake HD API: a state set by the test, updated on request.
#include "fake_world.hpp"

namespace cosmems::fake_hd {

extern "C" {

HDenum hdCheckCalibration(void) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdCheckCalibration");
  if (NoDevice(w)) return HD_CALIBRATION_NEEDS_MANUAL_INPUT;
  return w.calibration;
}

HDenum hdCheckCalibrationStyle(void) {
  auto lock = Lock();
  World& w = TheWorld();
  if (NoDevice(w)) return 0;
  return static_cast<HDenum>(w.specs.calibration_styles);
}

// One supported style at a time. Only a calibration that needs an update can be updated: one
// that needs the user (stylus into the inkwell) waits for hdFakeSetCalibration.
void hdUpdateCalibration(HDenum style) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdUpdateCalibration");
  if (NoDevice(w)) return;
  const HDenum supported = static_cast<HDenum>(w.specs.calibration_styles);
  const bool one_bit = style != 0 && (style & (style - 1)) == 0;
  if (!one_bit || (style & supported) == 0) {
    Raise(w, HD_INVALID_VALUE);
    return;
  }
  if (w.calibration == HD_CALIBRATION_NEEDS_UPDATE) w.calibration = HD_CALIBRATION_OK;
}

}  // extern "C"

}  // namespace cosmems::fake_hd
