// Device set-up, frames, capabilities and the error stack of the fake HD API.
#include <cmath>

#include "fake_world.hpp"

namespace cosmems::fake_hd {
namespace {

bool BadHandle(World& w, HHD handle) {
  if (w.initialized && handle == kDevice) return false;
  Raise(w, HD_BAD_HANDLE);
  return true;
}

// What the motors do with the frame's command: the device refuses a tick with an injected force
// error, keeps the force it had when the link fails (an amplifier holds its last command until
// told otherwise), outputs nothing while forces are off, clamps to its peak force when asked, and
// with the software limit raises an error rather than push harder than its peak.
void LatchForce(World& w) {
  const Injected injected = RaiseInjected(w);
  if (injected == Injected::kLinkError) return;
  w.latched_n = Vec3{};
  if (injected == Injected::kForceError || !w.force_output || !w.started) return;
  Vec3 force = w.commanded_n;
  const double norm = std::sqrt(force[0] * force[0] + force[1] * force[1] + force[2] * force[2]);
  const double peak = w.specs.max_force_n;
  if (w.max_force_clamping && norm > peak) {
    for (double& f : force) f *= peak / norm;
  } else if (w.software_force_limit && norm > peak) {
    Raise(w, HD_EXCEEDED_MAX_FORCE);
    return;
  }
  w.latched_n = force;
}

bool* Capability(World& w, HDenum cap) {
  switch (cap) {
    case HD_FORCE_OUTPUT:
      return &w.force_output;
    case HD_MAX_FORCE_CLAMPING:
      return &w.max_force_clamping;
    case HD_FORCE_RAMPING:
      return &w.force_ramping;
    case HD_SOFTWARE_FORCE_LIMIT:
      return &w.software_force_limit;
    case HD_ONE_FRAME_LIMIT:
      return &w.one_frame_limit;
    default:
      return nullptr;
  }
}

void SetCapability(HDenum cap, bool on, const char* call) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, call);
  if (NoDevice(w)) return;
  bool* flag = Capability(w, cap);
  if (flag == nullptr) {
    Raise(w, HD_INVALID_ENUM);
    return;
  }
  *flag = on;
  if (cap == HD_FORCE_OUTPUT && !on) w.latched_n = Vec3{};  // motors off: no force from now on
}

}  // namespace

// C-linkage functions declared here are the global ones of the HD headers.
extern "C" {

HHD hdInitDevice(HDstring /*pConfigName: the fake has one device, whatever its name*/) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdInitDevice");
  HDerror failure = HD_SUCCESS;
  if (w.init_failures_left > 0) {
    --w.init_failures_left;
    failure = w.init_failure;
  } else if (!w.device_present) {
    failure = HD_DEVICE_FAULT;
  } else if (w.initialized) {
    failure = HD_DEVICE_ALREADY_INITIATED;
  }
  if (failure != HD_SUCCESS) {
    Raise(w, failure);
    return HD_INVALID_HANDLE;
  }
  w.initialized = true;
  w.current = kDevice;
  // Power-on defaults: motors off until the scheduler starts, software force limit and the
  // one-frame rule on, no clamping or ramping.
  w.force_output = false;
  w.max_force_clamping = false;
  w.force_ramping = false;
  w.software_force_limit = true;
  w.one_frame_limit = true;
  w.sampled = false;
  SampleStylus(w, static_cast<double>(w.ticks) / static_cast<double>(w.rate_hz));
  return kDevice;
}

void hdMakeCurrentDevice(HHD hHD) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdMakeCurrentDevice");
  if (!BadHandle(w, hHD)) w.current = hHD;
}

void hdDisableDevice(HHD hHD) {
  auto lock = Lock();
  World& w = TheWorld();
  Record(w, "hdDisableDevice");
  if (BadHandle(w, hHD)) return;
  w.initialized = false;
  w.current = HD_INVALID_HANDLE;
  w.frame_depth = 0;
  w.latched_n = Vec3{};
}

HHD hdGetCurrentDevice(void) {
  auto lock = Lock();
  return TheWorld().current;
}

void hdBeginFrame(HHD hHD) {
  auto lock = Lock();
  World& w = TheWorld();
  if (BadHandle(w, hHD)) return;
  w.current = hHD;
  if (w.frame_depth > 0) {  // nested: shares the outer frame's snapshot and output
    ++w.frame_depth;
    return;
  }
  // Outside the scheduler's ticks there is no tick to limit frames to.
  if (OnTickingThread() && w.one_frame_limit && w.frame_done_this_tick) {
    Raise(w, HD_ILLEGAL_BEGIN);
    return;
  }
  w.frame_depth = 1;
  w.commanded_n = Vec3{};
}

void hdEndFrame(HHD hHD) {
  auto lock = Lock();
  World& w = TheWorld();
  if (BadHandle(w, hHD)) return;
  if (w.frame_depth == 0) {
    Raise(w, HD_ILLEGAL_END);
    return;
  }
  if (--w.frame_depth > 0) return;
  w.frame_done_this_tick = OnTickingThread();
  LatchForce(w);
}

HDErrorInfo hdGetError(void) {
  auto lock = Lock();
  World& w = TheWorld();
  if (w.errors.empty()) return HDErrorInfo{HD_SUCCESS, 0, w.current};
  const HDErrorInfo newest = w.errors.back();
  w.errors.pop_back();
  return newest;
}

void hdEnable(HDenum cap) { SetCapability(cap, true, "hdEnable"); }

void hdDisable(HDenum cap) { SetCapability(cap, false, "hdDisable"); }

HDboolean hdIsEnabled(HDenum cap) {
  auto lock = Lock();
  World& w = TheWorld();
  if (NoDevice(w)) return HD_FALSE;
  const bool* flag = Capability(w, cap);
  if (flag == nullptr) {
    Raise(w, HD_INVALID_ENUM);
    return HD_FALSE;
  }
  return *flag ? HD_TRUE : HD_FALSE;
}

}  // extern "C"

}  // namespace cosmems::fake_hd
