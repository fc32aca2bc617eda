#include "fake_world.hpp"

#include <algorithm>
#include <cstring>

namespace cosmems::fake_hd {
namespace {

std::mutex& WorldMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

std::unique_lock<std::mutex> Lock() { return std::unique_lock<std::mutex>(WorldMutex()); }

World& TheWorld() {
  static World world;
  return world;
}

std::condition_variable& Changed() {
  static std::condition_variable changed;
  return changed;
}

bool& OnTickingThread() {
  thread_local bool ticking = false;
  return ticking;
}

HDFakeSpecs DefaultSpecs() {
  HDFakeSpecs s{};
  std::strncpy(s.model, "PHANTOM Omni", sizeof(s.model) - 1);
  std::strncpy(s.vendor, "SensAble Technologies", sizeof(s.vendor) - 1);
  s.max_force_n = 3.3;
  s.max_continuous_force_n = 0.88;
  // CHAI3D's closed-loop figures for the Omni at 1 kHz (700 N/m, 5 N s/m), far below the
  // mechanism's own 1-2 N/mm: what a renderer can use without buzzing.
  s.max_stiffness_n_per_mm = 0.7;
  s.max_damping_ns_per_mm = 0.005;
  const double usable[6] = {-80.0, -60.0, -35.0, 80.0, 60.0, 35.0};
  // The Touch datasheet's range of motion (431 x 348 x 165 mm), centred.
  const double mechanical[6] = {-215.5, -174.0, -82.5, 215.5, 174.0, 82.5};
  std::copy(usable, usable + 6, s.usable_workspace_mm);
  std::copy(mechanical, mechanical + 6, s.max_workspace_mm);
  s.tabletop_offset_mm = 0.0;
  s.input_dof = 6;
  s.output_dof = 3;
  s.calibration_styles = HD_CALIBRATION_INKWELL;
  return s;
}

void Raise(World& w, HDerror code) {
  if (w.errors.size() == kMaxErrors) w.errors.erase(w.errors.begin());
  w.errors.push_back(HDErrorInfo{code, 0, w.current});
}

void Record(World& w, const char* call) { w.calls.push_back(call); }

bool NoDevice(World& w) {
  if (w.initialized) return false;
  Raise(w, HD_INVALID_OPERATION);
  return true;
}

void SampleStylus(World& w, double time_s) {
  Vec3 position = w.fixed_position_mm;
  if (w.motion != nullptr) w.motion(time_s, position.data(), w.motion_user);
  w.last = w.now;
  w.now.position_mm = position;
  w.now.buttons = w.buttons;
  const double rate = static_cast<double>(w.rate_hz);
  for (std::size_t i = 0; i < 3; ++i) {
    w.now.velocity_mm_s[i] = w.sampled ? (position[i] - w.last.position_mm[i]) * rate : 0.0;
  }
  w.sampled = true;
}

Injected RaiseInjected(World& w) {
  const HDulong tick = w.ticks - 1;
  Injected raised = Injected::kNone;
  auto due = [&](const InjectedError& e) {
    if (e.tick != tick) return false;
    Raise(w, e.code);
    // A failed link (hduIsSchedulerError's codes) outranks a refused force: nothing arrived.
    const bool link = e.code == HD_COMM_ERROR || e.code == HD_COMM_CONFIG_ERROR ||
                      e.code == HD_TIMER_ERROR || e.code == HD_INVALID_PRIORITY ||
                      e.code == HD_SCHEDULER_FULL;
    if (link) {
      raised = Injected::kLinkError;
    } else if (raised == Injected::kNone) {
      raised = Injected::kForceError;
    }
    return true;
  };
  w.injected.erase(std::remove_if(w.injected.begin(), w.injected.end(), due), w.injected.end());
  return raised;
}

}  // namespace cosmems::fake_hd
