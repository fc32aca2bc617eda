#pragma once

#include <HD/hd.h>
#include <HD/hd_fake.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cosmems/openhaptics/openhaptics_device.hpp"

namespace cosmems {

/// Every test starts from, and leaves behind, a powered-on fake with nothing initialised (the
/// fake is one per process, like the HD scheduler).
class FakeHdTest : public ::testing::Test {
 protected:
  void SetUp() override { hdFakeReset(); }
  void TearDown() override { hdFakeReset(); }
};

/// Forces reach the device unchanged: a slew limit no test force reaches, and a ramp-in of
/// `ramp_in_s` (none by default).
inline OpenHapticsOptions Immediate(double ramp_in_s = 0.0) {
  OpenHapticsOptions options;
  options.safety.ramp_in_s = ramp_in_s;
  options.safety.slew_limit_n_per_s = 1e6;
  return options;
}

/// Empties the error stack, newest error first.
inline std::vector<HDerror> PopErrors() {
  std::vector<HDerror> codes;
  for (HDErrorInfo e = hdGetError(); HD_DEVICE_ERROR(e); e = hdGetError()) {
    codes.push_back(e.errorCode);
  }
  return codes;
}

/// The set-up and shutdown calls the fake recorded, in order.
inline std::vector<std::string> RecordedCalls() {
  std::vector<std::string> calls;
  for (HDulong i = 0; i < hdFakeCallCount(); ++i) calls.emplace_back(hdFakeCall(i));
  return calls;
}

/// The force the fake output during `tick` [N].
inline std::vector<double> LoggedForce(HDulong tick) {
  std::vector<double> f(3);
  hdFakeForceLogEntry(tick, f.data());
  return f;
}

}  // namespace cosmems
