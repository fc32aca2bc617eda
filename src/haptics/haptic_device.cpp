#include "cosmems/haptics/haptic_device.hpp"

#include <chrono>

#include "cosmems/haptics/built_in_specs.hpp"

namespace cosmems {
namespace {

double NowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

constexpr std::uint64_t kPublishEvery = 100;  // ticks between two refreshes of stats()

}  // namespace

HapticDevice::HapticDevice(const SafetyOptions& safety) : safety_options_(safety) {
  safety.Validate();
}

DeviceStatus HapticDevice::Open() {
  if (open_) return DeviceStatus::kInvalidState;
  DeviceSpecs reported;
  const DeviceStatus status = OpenBackend(reported);
  if (status != DeviceStatus::kOk) return status;
  CompleteSpecs(reported);
  specs_ = reported;
  safety_ = std::make_unique<SafetyLayer>(safety_options_, specs_);
  figures_ = std::make_unique<TripleBuffer<Figures>>();
  open_ = true;
  return DeviceStatus::kOk;
}

CalibrationStatus HapticDevice::Calibration() {
  return open_ ? CheckCalibration() : CalibrationStatus::kNeedsManualInput;
}

double HapticDevice::force_limit_n() const { return safety_ ? safety_->force_limit() : 0.0; }

DeviceStatus HapticDevice::Start(ServoClient& client) {
  if (!open_ || running_) return DeviceStatus::kInvalidState;
  if (Paced() && client.BlocksTheTick()) return DeviceStatus::kRefused;
  client_ = &client;
  client.OnStart();
  safety_->Restart();
  recorder_.Start(safety_->period(), Paced(), Realtime());
  const DeviceStatus status = StartServo();
  running_ = status == DeviceStatus::kOk;
  return status;
}

void HapticDevice::Stop() noexcept {
  if (!running_) return;
  StopServo();
  running_ = false;
  PublishFigures();  // the servo thread has ended: this thread owns the figures now
}

void HapticDevice::Close() noexcept {
  Stop();
  if (!open_) return;
  CloseBackend();
  open_ = false;
}

Eigen::Vector3d HapticDevice::ServoTick(const DeviceState& state) noexcept {
  const double start_s = NowSeconds();
  if (recorder_.stats().ticks == 0) recorder_.MarkRealtime(Realtime());
  ForceCommand command;
  // A state the device got wrong, or cannot place yet (uncalibrated), is not shown to the
  // client; the safety layer zeroes the force.
  if (state.calibrated && SafetyLayer::Usable(state)) {
    client_->Tick(state, command);
  } else {
    command.valid = false;
  }
  const Eigen::Vector3d force = safety_->Filter(state, command);
  recorder_.Record(start_s, (NowSeconds() - start_s) * 1e6);
  if (recorder_.stats().ticks % kPublishEvery == 0) PublishFigures();
  return force;
}

Eigen::Vector3d HapticDevice::ServoRampDown() noexcept {
  safety_->RampDown();
  return safety_->last_output();
}

void HapticDevice::PublishFigures() {
  Figures& back = figures_->Back();
  back.loop = recorder_.stats();
  back.safety = safety_->counters();
  figures_->Publish();
}

HapticDevice::Figures HapticDevice::LatestFigures() const {
  std::lock_guard<std::mutex> lock(figures_reader_);
  if (figures_ && figures_->Update()) last_figures_ = figures_->Front();
  return last_figures_;
}

LoopStats HapticDevice::stats() const { return LatestFigures().loop; }

SafetyCounters HapticDevice::safety_counters() const { return LatestFigures().safety; }

}  // namespace cosmems
