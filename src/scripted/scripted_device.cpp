#include "cosmems/scripted/scripted_device.hpp"

#include <algorithm>
#include <cmath>
#include <future>
#include <stdexcept>
#include <system_error>

#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/periodic_deadline.hpp"
#include "cosmems/haptics/realtime_thread.hpp"

namespace cosmems {
namespace {

std::unique_ptr<const Trajectory> Checked(std::unique_ptr<const Trajectory> trajectory) {
  if (!trajectory) throw std::invalid_argument("scripted device: the trajectory is null");
  const double duration = trajectory->Duration();
  if (!(std::isfinite(duration) && duration >= 0.0)) {
    throw std::invalid_argument("scripted device: trajectory Duration() = " +
                                std::to_string(duration) + " must be finite and >= 0");
  }
  return trajectory;
}

/// Ticks n = 0, 1, ... with n / rate <= duration.
std::uint64_t TicksOver(double duration_s, double rate_hz) {
  // A duration of whole periods (6 s at 1 kHz) can land a rounding error below its tick count;
  // a millionth of a tick of slack keeps its last tick. The cap keeps the conversion defined
  // for absurd durations, whose storage would fail to allocate anyway.
  const double last = std::min(std::floor(duration_s * rate_hz + 1e-6), 1e18);
  return static_cast<std::uint64_t>(last) + 1;
}

// A recorded run keeps every tick (80 bytes) from Start(): beyond 1e7 ticks (800 MB, 2.8 hours
// at 1 kHz) a script is refused rather than left to exhaust memory.
constexpr std::uint64_t kMaxRecordedTicks = 10'000'000;

}  // namespace

ScriptedDevice::ScriptedDevice(std::unique_ptr<const Trajectory> trajectory,
                               const ScriptedOptions& options)
    : HapticDevice(options.safety), trajectory_(Checked(std::move(trajectory))), options_(options) {
  options_.Validate();
  DeviceSpecs specs = options_.specs;
  CompleteSpecs(specs);
  const std::uint64_t ticks = TicksOver(trajectory_->Duration(), specs.nominal_rate_hz);
  if (options_.record && ticks > kMaxRecordedTicks) {
    throw std::invalid_argument(
        "scripted device: trajectory Duration() = " + std::to_string(trajectory_->Duration()) +
        " s is " + std::to_string(ticks) + " ticks; a recorded run takes at most " +
        std::to_string(kMaxRecordedTicks));
  }
  realtime_note_ = options_.clock == ScriptedClock::kPaced
                       ? "not started"
                       : "real-time scheduling is asked for by the paced clock only: a thread "
                         "ticking back to back at SCHED_FIFO would starve the machine";
}

ScriptedDevice::~ScriptedDevice() {
  Stop();
  Close();
}

DeviceStatus ScriptedDevice::OpenBackend(DeviceSpecs& specs) {
  specs = options_.specs;
  return DeviceStatus::kOk;
}

CalibrationStatus ScriptedDevice::CheckCalibration() { return CalibrationStatus::kOk; }

// Nothing is held between Open() and Close(); the recording stays readable after Close().
void ScriptedDevice::CloseBackend() noexcept {}

DeviceStatus ScriptedDevice::StartServo() {
  rate_hz_ = specs().nominal_rate_hz;
  total_ticks_ = TicksOver(trajectory_->Duration(), rate_hz_);
  tick_ = 0;
  ticks_.store(0, std::memory_order_release);
  done_.store(false, std::memory_order_release);
  stop_requested_.store(false, std::memory_order_release);
  hand_ = SpringHand(options_.spring, 1.0 / rate_hz_);
  hand_.Reset(trajectory_->Position(0.0));
  // Filling the rows now, not just reserving them, also faults their pages in before the loop.
  // The stop's ramp follows the script's ticks.
  samples_.assign(options_.record ? total_ticks_ + MaxRampDownTicks() : 0, ScriptedSample{});
  if (options_.clock == ScriptedClock::kManual) return DeviceStatus::kOk;

  {
    std::lock_guard<std::mutex> lock(thread_mutex_);
    thread_ended_ = false;
  }
  std::promise<void> ready;
  std::future<void> started = ready.get_future();
  try {
    thread_ = std::thread([this, ready = std::move(ready)]() mutable {
      if (options_.clock == ScriptedClock::kPaced) {
        const RealtimeSetup setup = MakeThisThreadRealtime();
        realtime_.store(setup.realtime(), std::memory_order_release);
        realtime_note_ = setup.realtime() ? "SCHED_FIFO with locked memory" : setup.note;
      }
      ready.set_value();
      if (options_.clock == ScriptedClock::kPaced) {
        RunPaced();
      } else {
        RunFast();
      }
      {
        std::lock_guard<std::mutex> lock(thread_mutex_);
        thread_ended_ = true;
      }
      thread_ended_cv_.notify_all();
    });
  } catch (const std::system_error&) {
    std::lock_guard<std::mutex> lock(thread_mutex_);
    thread_ended_ = true;
    return DeviceStatus::kCommError;
  }
  // Realtime() and realtime_note() are settled before Start() returns.
  started.wait();
  return DeviceStatus::kOk;
}

// The servo thread ramps the force down itself once it sees the request; on the manual clock
// this thread runs the ramp's ticks (at most MaxRampDownTicks()).
void ScriptedDevice::StopServo() noexcept {
  stop_requested_.store(true, std::memory_order_release);
  if (thread_.joinable()) thread_.join();
  if (options_.clock == ScriptedClock::kManual) {
    while (!Finished()) Tick();
  }
}

std::uint64_t ScriptedDevice::Step(std::uint64_t n) {
  if (options_.clock != ScriptedClock::kManual) {
    throw std::logic_error("ScriptedDevice::Step() needs the manual clock");
  }
  if (!is_running()) return 0;
  std::uint64_t ran = 0;
  for (; ran < n && !Done(); ++ran) Tick();
  return ran;
}

void ScriptedDevice::WaitUntilDone() {
  std::unique_lock<std::mutex> lock(thread_mutex_);
  thread_ended_cv_.wait(lock, [this] { return thread_ended_; });
}

void ScriptedDevice::RunPaced() noexcept {
  PeriodicDeadline deadline(rate_hz_);
  while (!Finished()) {
    Tick();
    deadline.SleepUntilNext();
  }
}

void ScriptedDevice::RunFast() noexcept {
  while (!Finished()) Tick();
}

void ScriptedDevice::Tick() noexcept {
  const std::uint64_t n = tick_;
  // After the script's last tick, or once a stop is asked for, the force comes down to zero
  // along the slew limit while the hand holds its last target.
  const bool ramp = n >= total_ticks_ || stop_requested_.load(std::memory_order_acquire);
  const double t = static_cast<double>(n) / rate_hz_;
  Eigen::Vector3d target = previous_target_;
  // Backward difference, the velocity the script implies over the last tick; zero at the first
  // tick, just after a non-finite position (nothing finite to difference) and in the ramp.
  Eigen::Vector3d target_velocity = Eigen::Vector3d::Zero();
  if (!ramp) {
    target = trajectory_->Position(t);
    if (n > 0 && previous_target_.allFinite()) {
      target_velocity = (target - previous_target_) * rate_hz_;
    }
    previous_target_ = target;
  }

  const bool spring = options_.hand == HandModel::kSpring;
  // A non-finite script point reaches the device state as it is (the safety layer's business);
  // the hand restarts from the script once it is finite again, so NaN does not stick.
  if (spring && !(target.allFinite() && hand_.finite())) hand_.Reset(target);
  DeviceState state;
  state.tick = n;
  state.time_s = t;
  state.position_m = spring ? hand_.position() : target;
  state.velocity_m_s = spring ? hand_.velocity() : target_velocity;

  const Eigen::Vector3d force = ramp ? ServoRampDown() : ServoTick(state);
  if (spring) hand_.Step(target, target_velocity, force);
  if (n < samples_.size()) {
    samples_[n] = ScriptedSample{t, state.position_m, state.velocity_m_s, force};
  }
  tick_ = n + 1;
  ticks_.store(tick_, std::memory_order_release);  // publishes the row just written
  // The script is over once its ticks have run and the force is zero after them (at once when
  // it ended at zero: nothing to ramp down).
  if (tick_ >= total_ticks_ && ForceAtRest()) done_.store(true, std::memory_order_release);
}

std::vector<ScriptedSample> ScriptedDevice::Recorded() const {
  const std::size_t rows = options_.record ? static_cast<std::size_t>(ticks()) : 0;
  return std::vector<ScriptedSample>(samples_.begin(),
                                     samples_.begin() + static_cast<std::ptrdiff_t>(rows));
}

void ScriptedDevice::WriteCsv(const std::string& path) const { WriteSamplesCsv(path, Recorded()); }

}  // namespace cosmems
