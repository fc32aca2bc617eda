// The test hooks of hd_fake.h.
#include <algorithm>

#include "fake_world.hpp"

namespace cosmems::fake_hd {

extern "C" {

void hdFakeReset(void) {
  std::thread serving;
  {
    auto lock = Lock();
    World& w = TheWorld();
    w.stop_requested = true;
    serving = std::move(w.thread);
  }
  if (serving.joinable()) serving.join();
  auto lock = Lock();
  TheWorld() = World();
  Changed().notify_all();
}

void hdFakeDefaultSpecs(HDFakeSpecs* specs) { *specs = DefaultSpecs(); }

void hdFakeSetSpecs(const HDFakeSpecs* specs) {
  auto lock = Lock();
  TheWorld().specs = *specs;
}

void hdFakeSetManualTicks(HDboolean manual) {
  auto lock = Lock();
  TheWorld().manual_ticks = manual != HD_FALSE;
}

HDulong hdFakeStep(HDulong count) {
  {
    auto lock = Lock();
    const World& w = TheWorld();
    if (!w.started || !w.manual_ticks || OnTickingThread()) return 0;
  }
  for (HDulong i = 0; i < count; ++i) RunTick();
  return count;
}

HDulong hdFakeTickCount(void) {
  auto lock = Lock();
  return TheWorld().ticks;
}

void hdFakeSetMotion(HDFakeMotion motion, void* user) {
  auto lock = Lock();
  TheWorld().motion = motion;
  TheWorld().motion_user = user;
}

void hdFakeSetPosition(const HDdouble position_mm[3]) {
  auto lock = Lock();
  World& w = TheWorld();
  w.motion = nullptr;
  std::copy(position_mm, position_mm + 3, w.fixed_position_mm.begin());
}

void hdFakeSetButtons(HDint buttons) {
  auto lock = Lock();
  TheWorld().buttons = buttons;
}

void hdFakeSetCalibration(HDenum status) {
  auto lock = Lock();
  TheWorld().calibration = status;
}

void hdFakeInjectError(HDerror code, HDulong tick) {
  auto lock = Lock();
  TheWorld().injected.push_back(InjectedError{code, tick});
}

void hdFakeFailInit(HDerror code, HDint count) {
  auto lock = Lock();
  TheWorld().init_failure = code;
  TheWorld().init_failures_left = count;
}

void hdFakeSetDevicePresent(HDboolean present) {
  auto lock = Lock();
  TheWorld().device_present = present != HD_FALSE;
}

void hdFakeLatchedForce(HDdouble force_n[3]) {
  auto lock = Lock();
  const Vec3& f = TheWorld().latched_n;
  std::copy(f.begin(), f.end(), force_n);
}

HDulong hdFakeForceLogSize(void) {
  auto lock = Lock();
  return TheWorld().force_log.size();
}

void hdFakeForceLogEntry(HDulong tick, HDdouble force_n[3]) {
  auto lock = Lock();
  const std::vector<Vec3>& log = TheWorld().force_log;
  const Vec3 f = tick < log.size() ? log[tick] : Vec3{};
  std::copy(f.begin(), f.end(), force_n);
}

HDulong hdFakeCallCount(void) {
  auto lock = Lock();
  return TheWorld().calls.size();
}

HDstring hdFakeCall(HDulong index) {
  auto lock = Lock();
  const std::vector<const char*>& calls = TheWorld().calls;
  return index < calls.size() ? calls[index] : nullptr;
}

}  // extern "C"

}  // namespace cosmems::fake_hd
