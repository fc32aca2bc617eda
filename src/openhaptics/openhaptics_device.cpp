#include "cosmems/openhaptics/openhaptics_device.hpp"

#include <HD/hd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

namespace cosmems {
namespace {

constexpr int kInitRetries = 10;  // SOFA's driver gives a stale initialisation ten tries
constexpr int kMaxErrors = 64;    // more than the stack holds: draining always ends

// hduIsForceError's rule, plus the impulse limit: the device refused this tick's force, the loop
// may go on. Reimplemented so that the library needs only libHD.
bool IsForceError(HDerror code) {
  return code == HD_WARM_MOTORS || code == HD_EXCEEDED_MAX_FORCE ||
         code == HD_EXCEEDED_MAX_FORCE_IMPULSE || code == HD_EXCEEDED_MAX_VELOCITY ||
         code == HD_FORCE_ERROR;
}

// hduIsSchedulerError's rule: the servo loop cannot go on.
bool IsSchedulerError(HDerror code) {
  return code == HD_COMM_ERROR || code == HD_COMM_CONFIG_ERROR || code == HD_TIMER_ERROR ||
         code == HD_INVALID_PRIORITY || code == HD_SCHEDULER_FULL;
}

// Empties the error stack; returns its oldest entry (the cause of the rest), or HD_SUCCESS.
HDErrorInfo DrainErrors() {
  HDErrorInfo oldest{HD_SUCCESS, 0, HD_INVALID_HANDLE};
  for (int i = 0; i < kMaxErrors; ++i) {
    const HDErrorInfo error = hdGetError();
    if (!HD_DEVICE_ERROR(error)) break;
    oldest = error;
  }
  return oldest;
}

// A value the device may not report (older devices lack some): 0 then, which leaves the field
// to the built-in table.
double ReadDouble(HDenum parameter) {
  HDdouble value = 0.0;
  hdGetDoublev(parameter, &value);
  return HD_DEVICE_ERROR(DrainErrors()) ? 0.0 : value;
}

std::string ReadString(HDenum parameter) {
  const HDstring value = hdGetString(parameter);
  return HD_DEVICE_ERROR(DrainErrors()) || value == nullptr ? std::string() : std::string(value);
}

HDenum PreferredStyle(HDint styles) {
  for (const HDint style :
       {HD_CALIBRATION_AUTO, HD_CALIBRATION_INKWELL, HD_CALIBRATION_ENCODER_RESET}) {
    if ((styles & style) != 0) return static_cast<HDenum>(style);
  }
  return 0;
}

// Checks the calibration and updates it when the device can do that alone. Call it in a frame.
HDenum Calibrate(HDint styles) {
  HDenum status = hdCheckCalibration();
  const HDenum style = PreferredStyle(styles);
  if (status == HD_CALIBRATION_NEEDS_UPDATE && style != 0) {
    hdUpdateCalibration(style);
    status = hdCheckCalibration();
  }
  return status;
}

// The devices this process's OpenHapticsDevices hold, by configured name. hdInitDevice cannot
// tell a live session in this process from a handle a crash left behind, so the claim does: a
// second Open() of a claimed device is refused before the HD API is asked.
class DeviceClaims {
 public:
  static bool Claim(const std::string& name) {
    std::lock_guard<std::mutex> lock(Mutex());
    return Held().insert(name).second;
  }
  static void Release(const std::string& name) {
    std::lock_guard<std::mutex> lock(Mutex());
    Held().erase(name);
  }

 private:
  static std::mutex& Mutex() {
    static std::mutex mutex;
    return mutex;
  }
  static std::set<std::string>& Held() {
    static std::set<std::string> held;
    return held;
  }
};

CalibrationStatus ToStatus(HDenum status) {
  switch (status) {
    case HD_CALIBRATION_OK:
      return CalibrationStatus::kOk;
    case HD_CALIBRATION_NEEDS_UPDATE:
      return CalibrationStatus::kNeedsUpdate;
    default:
      return CalibrationStatus::kNeedsManualInput;
  }
}

}  // namespace

struct OpenHapticsDevice::Session {
  // Set up and read by the controlling thread.
  HHD device = HD_INVALID_HANDLE;
  HDSchedulerHandle servo = 0;
  HDint calibration_styles = 0;
  double rate_hz = 1000.0;
  bool running = false;
  std::string claim;  // the name this device is claimed under while open

  // The servo thread's, between StartServo() and StopServo().
  std::uint64_t tick = 0;
  bool fault_pending = false;  // a force error at the last tick: tell the next one
  bool forces_on = false;      // HD_FORCE_OUTPUT as this loop last set it

  // Shared.
  std::atomic<HDenum> calibration{HD_CALIBRATION_OK};
  std::atomic<bool> ended{false};       // a scheduler error ended the callback
  std::atomic<bool> stopping{false};    // StopServo() asks the ticks to ramp the force down
  std::atomic<bool> ramped{false};      // the force is zero and its output off; the callback ended
  std::atomic<std::uint64_t> error{0};  // errorCode << 32 | internalErrorCode, in one piece

  void Record(const HDErrorInfo& e) {
    if (!HD_DEVICE_ERROR(e)) return;
    error.store(static_cast<std::uint64_t>(e.errorCode) << 32 |
                static_cast<std::uint32_t>(e.internalErrorCode));
  }

  static HDCallbackCode HDCALLBACK Servo(void* user_data);
  HDCallbackCode Tick(OpenHapticsDevice& owner) noexcept;
  HDCallbackCode Triage() noexcept;
};

HDCallbackCode HDCALLBACK OpenHapticsDevice::Session::Servo(void* user_data) {
  auto& owner = *static_cast<OpenHapticsDevice*>(user_data);
  return owner.session_->Tick(owner);
}

// One tick: the stylus in SI in, the safety layer's force out, inside one frame. Beginning the
// frame on our own handle also makes it current, whatever other device ran before.
HDCallbackCode OpenHapticsDevice::Session::Tick(OpenHapticsDevice& owner) noexcept {
  hdBeginFrame(device);
  // A read that fails leaves NaN, which the safety layer takes as a device fault.
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  HDdouble position_mm[3] = {kNaN, kNaN, kNaN};
  HDdouble velocity_mm_s[3] = {kNaN, kNaN, kNaN};
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();  // column-major, as HD's
  HDint buttons = 0;
  hdGetDoublev(HD_CURRENT_POSITION, position_mm);
  hdGetDoublev(HD_CURRENT_VELOCITY, velocity_mm_s);
  hdGetDoublev(HD_CURRENT_TRANSFORM, transform.data());
  hdGetIntegerv(HD_CURRENT_BUTTONS, &buttons);

  DeviceState state;
  state.tick = tick;
  state.time_s = static_cast<double>(tick) / rate_hz;
  state.position_m = 1e-3 * Eigen::Map<const Eigen::Vector3d>(position_mm);
  state.velocity_m_s = 1e-3 * Eigen::Map<const Eigen::Vector3d>(velocity_mm_s);
  state.orientation = transform.topLeftCorner<3, 3>();
  state.buttons = static_cast<std::uint32_t>(buttons);
  state.fault = fault_pending;
  fault_pending = false;
  // An inkwell calibration completes only while the scheduler runs: keep checking until it has.
  if (calibration.load(std::memory_order_relaxed) != HD_CALIBRATION_OK) {
    calibration.store(Calibrate(calibration_styles), std::memory_order_relaxed);
  }
  // An uncalibrated device places the stylus wrongly, so a force computed from it pushes the
  // hand the wrong way: the motors stay off until the calibration is OK, and the safety layer
  // holds the force at zero meanwhile (so that it ramps in once they come on).
  state.calibrated = calibration.load(std::memory_order_relaxed) == HD_CALIBRATION_OK;
  if (state.calibrated != forces_on) {
    state.calibrated ? hdEnable(HD_FORCE_OUTPUT) : hdDisable(HD_FORCE_OUTPUT);
    forces_on = state.calibrated;
  }

  const bool stop = stopping.load(std::memory_order_acquire);
  const Eigen::Vector3d force_n = stop ? owner.ServoRampDown() : owner.ServoTick(state);
  hdSetDoublev(HD_CURRENT_FORCE, force_n.data());
  hdEndFrame(device);
  ++tick;
  if (stop && owner.ForceAtRest()) {
    // The zero force is latched: the motors go off before the scheduler stops.
    hdDisable(HD_FORCE_OUTPUT);
    Triage();
    ramped.store(true, std::memory_order_release);
    return HD_CALLBACK_DONE;
  }
  return Triage();
}

// The pattern of the SDK's examples: a force error drops the force and the loop goes on; a
// scheduler error ends it.
HDCallbackCode OpenHapticsDevice::Session::Triage() noexcept {
  bool fatal = false;
  for (int i = 0; i < kMaxErrors; ++i) {
    const HDErrorInfo e = hdGetError();
    if (!HD_DEVICE_ERROR(e)) break;
    Record(e);
    fatal = fatal || IsSchedulerError(e.errorCode);
    fault_pending = fault_pending || IsForceError(e.errorCode);
  }
  if (!fatal) return HD_CALLBACK_CONTINUE;
  // The link failed: the frame's command may never have arrived and the amplifiers may hold the
  // last force, with no tick left to bring it down. Motors off now, not at the next Stop().
  hdDisable(HD_FORCE_OUTPUT);
  forces_on = false;
  DrainErrors();  // the disable's own complaint over a dead link is not news
  ended.store(true);
  return HD_CALLBACK_DONE;
}

OpenHapticsDevice::OpenHapticsDevice(const OpenHapticsOptions& options)
    : HapticDevice(options.safety), options_(options), session_(std::make_unique<Session>()) {
  if (options.scheduler_rate_hz <= 0) {
    throw std::invalid_argument("scheduler_rate_hz = " + std::to_string(options.scheduler_rate_hz) +
                                " is not positive");
  }
  session_->rate_hz = options.scheduler_rate_hz;
}

OpenHapticsDevice::~OpenHapticsDevice() {
  Stop();
  Close();
}

OpenHapticsError OpenHapticsDevice::last_error() const {
  const std::uint64_t packed = session_->error.load();
  OpenHapticsError e;
  e.code = static_cast<unsigned int>(packed >> 32);
  e.internal_code = static_cast<int>(static_cast<std::uint32_t>(packed));
  if (e.code != HD_SUCCESS) e.description = hdGetErrorString(e.code);
  return e;
}

bool OpenHapticsDevice::BuiltWithSdk() {
#ifdef COSMEMS_OPENHAPTICS_WITH_SDK
  return true;
#else
  return false;
#endif
}

bool OpenHapticsDevice::servo_ended() const { return session_->ended.load(); }

DeviceStatus OpenHapticsDevice::OpenBackend(DeviceSpecs& specs) {
  Session& s = *session_;
  DrainErrors();  // earlier calls' errors are not this one's
  const HDstring name =
      options_.device_name.empty() ? HD_DEFAULT_DEVICE : options_.device_name.c_str();
  // By the configured name; empty is the default device (HD_DEFAULT_DEVICE is a null name).
  if (!DeviceClaims::Claim(options_.device_name)) {
    // A live session of this process has it: leave that session's device alone.
    s.Record(HDErrorInfo{HD_DEVICE_ALREADY_INITIATED, 0, HD_INVALID_HANDLE});
    return DeviceStatus::kAlreadyInUse;
  }
  s.claim = options_.device_name;
  HHD device = hdInitDevice(name);
  HDErrorInfo error = DrainErrors();
  // After a crash the driver may still hold the device: no live session here claims it (see
  // above), so release what this process holds and try again. A device held by another program
  // stays refused.
  for (int i = 0; i < kInitRetries && error.errorCode == HD_DEVICE_ALREADY_INITIATED; ++i) {
    const HHD stale = hdGetCurrentDevice();
    if (stale != HD_INVALID_HANDLE) hdDisableDevice(stale);
    DrainErrors();
    device = hdInitDevice(name);
    error = DrainErrors();
  }
  if (HD_DEVICE_ERROR(error) || device == HD_INVALID_HANDLE) {
    s.Record(error);
    DeviceClaims::Release(s.claim);
    s.claim.clear();
    return error.errorCode == HD_DEVICE_ALREADY_INITIATED ? DeviceStatus::kAlreadyInUse
                                                          : DeviceStatus::kNotFound;
  }
  s.device = device;
  hdMakeCurrentDevice(device);

  // The HD API's units are mm and N; DeviceSpecs' are SI. It reports neither the button count
  // nor the encoder resolution: those stay 0 for the built-in table.
  specs.model = ReadString(HD_DEVICE_MODEL_TYPE);
  specs.vendor = ReadString(HD_DEVICE_VENDOR);
  specs.max_force_n = ReadDouble(HD_NOMINAL_MAX_FORCE);
  specs.max_continuous_force_n = ReadDouble(HD_NOMINAL_MAX_CONTINUOUS_FORCE);
  specs.max_stiffness_n_per_m = 1e3 * ReadDouble(HD_NOMINAL_MAX_STIFFNESS);
  specs.max_damping_ns_per_m = 1e3 * ReadDouble(HD_NOMINAL_MAX_DAMPING);
  HDdouble box_mm[6] = {};
  hdGetDoublev(HD_USABLE_WORKSPACE_DIMENSIONS, box_mm);
  if (!HD_DEVICE_ERROR(DrainErrors())) {
    specs.workspace_min_m = 1e-3 * Eigen::Map<const Eigen::Vector3d>(box_mm);
    specs.workspace_max_m = 1e-3 * Eigen::Map<const Eigen::Vector3d>(box_mm + 3);
  }
  specs.nominal_rate_hz = s.rate_hz;
  hdGetIntegerv(HD_CALIBRATION_STYLE, &s.calibration_styles);
  if (HD_DEVICE_ERROR(DrainErrors())) s.calibration_styles = 0;
  return DeviceStatus::kOk;
}

CalibrationStatus OpenHapticsDevice::CheckCalibration() {
  Session& s = *session_;
  if (!s.running) {
    hdMakeCurrentDevice(s.device);
    hdBeginFrame(s.device);
    s.calibration.store(Calibrate(s.calibration_styles));
    hdEndFrame(s.device);
    s.Record(DrainErrors());
  }
  return ToStatus(s.calibration.load());
}

DeviceStatus OpenHapticsDevice::StartServo() {
  Session& s = *session_;
  CheckCalibration();  // tells the loop whether it still has to watch the calibration
  hdMakeCurrentDevice(s.device);
  // Starting the scheduler turns the motors on; the first tick turns them off again while the
  // device is not calibrated (Session::Tick).
  hdEnable(HD_FORCE_OUTPUT);
  hdEnable(HD_MAX_FORCE_CLAMPING);  // the device's own clamp, behind the safety layer's
  hdSetSchedulerRate(static_cast<HDulong>(options_.scheduler_rate_hz));
  HDErrorInfo error = DrainErrors();
  if (HD_DEVICE_ERROR(error)) {
    s.Record(error);
    return DeviceStatus::kCommError;
  }
  s.tick = 0;
  s.fault_pending = false;
  s.forces_on = true;
  s.ended.store(false);
  s.stopping.store(false);
  s.ramped.store(false);
  s.servo = hdScheduleAsynchronous(&Session::Servo, this, HD_MAX_SCHEDULER_PRIORITY);
  error = DrainErrors();
  if (HD_DEVICE_ERROR(error)) {
    s.Record(error);
    return DeviceStatus::kCommError;
  }
  hdStartScheduler();
  error = DrainErrors();
  if (HD_DEVICE_ERROR(error)) {
    s.Record(error);
    hdStopScheduler();
    hdUnschedule(s.servo);
    DrainErrors();
    return DeviceStatus::kCommError;
  }
  s.running = true;
  return DeviceStatus::kOk;
}

// The stop: the servo ticks bring the force down along the slew limit, latch zero and turn the
// force output off, and the callback ends itself (Session::Tick). Then the SDK's shutdown order:
// stop the scheduler (no tick runs after it returns), remove the callback unless it has ended.
// A scheduler that no longer ticks cannot ramp: after the ramp's time (with slack for a loaded
// machine) the output is turned off once the scheduler has stopped.
void OpenHapticsDevice::StopServo() noexcept {
  Session& s = *session_;
  s.stopping.store(true, std::memory_order_release);
  const double ramp_s = static_cast<double>(MaxRampDownTicks() + 1) / s.rate_hz;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(4.0 * ramp_s + 0.1);
  while (!s.ramped.load(std::memory_order_acquire) && !s.ended.load() &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  hdStopScheduler();
  if (!s.ended.load() && !s.ramped.load()) hdUnschedule(s.servo);
  if (!s.ramped.load()) {
    hdMakeCurrentDevice(s.device);
    hdDisable(HD_FORCE_OUTPUT);
  }
  s.Record(DrainErrors());
  s.running = false;
}

void OpenHapticsDevice::CloseBackend() noexcept {
  Session& s = *session_;
  hdDisableDevice(s.device);
  s.Record(DrainErrors());
  s.device = HD_INVALID_HANDLE;
  DeviceClaims::Release(s.claim);
  s.claim.clear();
}

}  // namespace cosmems
