// hdGet* / hdSet* of the fake HD API: what the device reports, in the SDK's units.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <type_traits>

#include "fake_world.hpp"

namespace cosmems::fake_hd {
namespace {

constexpr int kMaxValues = 16;  // a transform

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Manual ticks follow no clock: they report the nominal rate, as would an ideal scheduler.
double InstantaneousRate(const World& w) {
  if (w.manual_ticks || w.timed_ticks < 2) return static_cast<double>(w.rate_hz);
  return 1.0 / Seconds(w.tick_start - w.previous_tick_start);
}

double AverageRate(const World& w) {
  if (w.manual_ticks || w.timed_ticks < 2) return static_cast<double>(w.rate_hz);
  return static_cast<double>(w.timed_ticks - 1) / Seconds(w.tick_start - w.first_tick_start);
}

int Copy(const double* from, int count, double* to) {
  std::copy(from, from + count, to);
  return count;
}

int One(double value, double* to) { return Copy(&value, 1, to); }

// Column-major 4 x 4: the fake's stylus never turns, so only the translation changes.
int Transform(const Vec3& position_mm, double* to) {
  std::fill(to, to + 16, 0.0);
  to[0] = to[5] = to[10] = to[15] = 1.0;
  std::copy(position_mm.begin(), position_mm.end(), to + 12);
  return 16;
}

// The value of a numeric parameter; returns how many values, 0 when the fake does not know it.
int Read(const World& w, HDenum pname, double* to) {
  const HDFakeSpecs& s = w.specs;
  switch (pname) {
    case HD_CURRENT_BUTTONS:
      return One(w.now.buttons, to);
    case HD_CURRENT_SAFETY_SWITCH:
      return One(1.0, to);
    case HD_CURRENT_INKWELL_SWITCH:  // 1: the stylus is out of its inkwell
      return One(1.0, to);
    case HD_CURRENT_POSITION:
      return Copy(w.now.position_mm.data(), 3, to);
    case HD_CURRENT_VELOCITY:
      return Copy(w.now.velocity_mm_s.data(), 3, to);
    case HD_CURRENT_TRANSFORM:
      return Transform(w.now.position_mm, to);
    case HD_LAST_BUTTONS:
      return One(w.last.buttons, to);
    case HD_LAST_POSITION:
      return Copy(w.last.position_mm.data(), 3, to);
    case HD_LAST_VELOCITY:
      return Copy(w.last.velocity_mm_s.data(), 3, to);
    case HD_LAST_TRANSFORM:
      return Transform(w.last.position_mm, to);
    case HD_CURRENT_FORCE:
      return Copy(w.commanded_n.data(), 3, to);
    case HD_LAST_FORCE:
      return Copy(w.last_latched_n.data(), 3, to);
    case HD_DEVICE_FIRMWARE_VERSION:
      return One(1.0, to);
    case HD_MAX_WORKSPACE_DIMENSIONS:
      return Copy(s.max_workspace_mm, 6, to);
    case HD_USABLE_WORKSPACE_DIMENSIONS:
      return Copy(s.usable_workspace_mm, 6, to);
    case HD_TABLETOP_OFFSET:
      return One(s.tabletop_offset_mm, to);
    case HD_INPUT_DOF:
      return One(s.input_dof, to);
    case HD_OUTPUT_DOF:
      return One(s.output_dof, to);
    case HD_CALIBRATION_STYLE:
      return One(s.calibration_styles, to);
    case HD_UPDATE_RATE:
      return One(AverageRate(w), to);
    case HD_INSTANTANEOUS_UPDATE_RATE:
      return One(InstantaneousRate(w), to);
    case HD_NOMINAL_MAX_STIFFNESS:
      return One(s.max_stiffness_n_per_mm, to);
    case HD_NOMINAL_MAX_DAMPING:
      return One(s.max_damping_ns_per_mm, to);
    case HD_NOMINAL_MAX_FORCE:
      return One(s.max_force_n, to);
    case HD_NOMINAL_MAX_CONTINUOUS_FORCE:
      return One(s.max_continuous_force_n, to);
    default:
      return 0;
  }
}

bool IsString(HDenum pname) { return pname >= HD_VERSION && pname <= HD_DEVICE_SERIAL_NUMBER; }

template <class T>
T Convert(double value) {
  if constexpr (std::is_same_v<T, HDboolean>) {
    return value != 0.0 ? HD_TRUE : HD_FALSE;
  } else if constexpr (std::is_integral_v<T>) {
    return static_cast<T>(std::llround(value));
  } else {
    return static_cast<T>(value);
  }
}

template <class T>
void Get(HDenum pname, T* params) {
  auto lock = Lock();
  World& w = TheWorld();
  if (NoDevice(w)) return;
  if (IsString(pname)) {
    Raise(w, HD_INVALID_INPUT_TYPE);
    return;
  }
  double values[kMaxValues];
  const int count = Read(w, pname, values);
  if (count == 0) {
    Raise(w, HD_INVALID_ENUM);
    return;
  }
  for (int i = 0; i < count; ++i) params[i] = Convert<T>(values[i]);
}

// The fake commands force only; a force outside a frame would go nowhere, so it is an error.
template <class T>
void Set(HDenum pname, const T* params) {
  auto lock = Lock();
  World& w = TheWorld();
  if (NoDevice(w)) return;
  if (pname != HD_CURRENT_FORCE) {
    Raise(w, HD_INVALID_ENUM);
    return;
  }
  if (w.frame_depth == 0) {
    Raise(w, HD_INVALID_OPERATION);
    return;
  }
  for (std::size_t i = 0; i < 3; ++i) w.commanded_n[i] = static_cast<double>(params[i]);
}

}  // namespace

extern "C" {

void hdGetBooleanv(HDenum pname, HDboolean* params) { Get(pname, params); }
void hdGetIntegerv(HDenum pname, HDint* params) { Get(pname, params); }
void hdGetFloatv(HDenum pname, HDfloat* params) { Get(pname, params); }
void hdGetDoublev(HDenum pname, HDdouble* params) { Get(pname, params); }
void hdGetLongv(HDenum pname, HDlong* params) { Get(pname, params); }

void hdSetBooleanv(HDenum pname, const HDboolean* params) { Set(pname, params); }
void hdSetIntegerv(HDenum pname, const HDint* params) { Set(pname, params); }
void hdSetFloatv(HDenum pname, const HDfloat* params) { Set(pname, params); }
void hdSetDoublev(HDenum pname, const HDdouble* params) { Set(pname, params); }
void hdSetLongv(HDenum pname, const HDlong* params) { Set(pname, params); }

// The strings live as long as the specs: until the next hdFakeSetSpecs or hdFakeReset.
HDstring hdGetString(HDenum pname) {
  auto lock = Lock();
  World& w = TheWorld();
  if (NoDevice(w)) return nullptr;
  switch (pname) {
    case HD_VERSION:
      return "cosmems fake HD 1.0";
    case HD_DEVICE_MODEL_TYPE:
      return w.specs.model;
    case HD_DEVICE_DRIVER_VERSION:
      return "none";
    case HD_DEVICE_VENDOR:
      return w.specs.vendor;
    case HD_DEVICE_SERIAL_NUMBER:
      return "00000";
    default: {
      double values[kMaxValues];
      Raise(w, Read(w, pname, values) > 0 ? HD_INVALID_INPUT_TYPE : HD_INVALID_ENUM);
      return nullptr;
    }
  }
}

}  // extern "C"

}  // namespace cosmems::fake_hd
