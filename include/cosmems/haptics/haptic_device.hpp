#pragma once

#include <atomic>
#include <memory>
#include <mutex>

#include "cosmems/haptics/device_types.hpp"
#include "cosmems/haptics/loop_stats.hpp"
#include "cosmems/haptics/safety_layer.hpp"
#include "cosmems/haptics/servo_client.hpp"
#include "cosmems/haptics/triple_buffer.hpp"

namespace cosmems {

/// A haptic device as the library sees it: open, check calibration, start a servo loop that
/// calls a ServoClient once a tick, stop, close; specs and loop figures in SI.
///
/// The backend owns the servo clock (OpenHaptics allows device calls only on its scheduler
/// thread); this base class owns everything every backend must do the same way: each tick goes
/// client -> SafetyLayer -> device through ServoTick(), which also times it. A backend implements
/// the protected hooks and calls ServoTick() on its servo thread once per tick. A derived class
/// calls Stop() and Close() in its own destructor (the base's cannot reach its hooks).
class HapticDevice {
 public:
  explicit HapticDevice(const SafetyOptions& safety = {});
  virtual ~HapticDevice() = default;
  HapticDevice(const HapticDevice&) = delete;
  HapticDevice& operator=(const HapticDevice&) = delete;

  /// Connects and reads the specs; what the device does not report comes from BuiltInSpecs().
  /// Motors stay off.
  DeviceStatus Open();
  /// The device's calibration (after Open()).
  CalibrationStatus Calibration();
  /// Starts the servo loop with `client` (which must outlive Stop()); forces ramp in. A paced
  /// device refuses a client whose tick may block (ServoClient::BlocksTheTick): kRefused.
  DeviceStatus Start(ServoClient& client);
  /// Brings the force down to zero along the slew limit, then stops the loop; idempotent.
  void Stop() noexcept;
  /// Releases the device; idempotent (stops first).
  void Close() noexcept;

  bool is_open() const { return open_; }
  bool is_running() const { return running_; }
  const DeviceSpecs& specs() const { return specs_; }
  /// The force limit the safety layer enforces [N] (after Open()).
  double force_limit_n() const;
  /// The most ticks a stop's ramp takes (after Open()).
  long MaxRampDownTicks() const { return safety_ ? safety_->MaxRampDownTicks() : 0; }

  /// Loop figures and safety counters: refreshed every 100 ticks while running, complete after
  /// Stop(). Callable from any thread but the servo thread.
  LoopStats stats() const;
  SafetyCounters safety_counters() const;

 protected:
  /// Connects; fills what the device reports into `specs` (zeros elsewhere).
  virtual DeviceStatus OpenBackend(DeviceSpecs& specs) = 0;
  virtual CalibrationStatus CheckCalibration() = 0;
  /// Begins calling ServoTick() once per tick on the servo thread.
  virtual DeviceStatus StartServo() = 0;
  /// Brings the force to zero with ticks of ServoRampDown() (at most MaxRampDownTicks()), then
  /// ends the ticks; after it returns, no tick is running and none will run again.
  virtual void StopServo() noexcept = 0;
  virtual void CloseBackend() noexcept = 0;
  /// True when the ticks follow the wall clock (deadline misses count only then).
  virtual bool Paced() const = 0;
  /// True when the servo thread runs with real-time priority (reported in the stats).
  virtual bool Realtime() const { return false; }

  /// One servo tick: runs the client on `state`, filters its force through the safety layer and
  /// returns what to send [N, device frame]: finite, within the limit and the slew rate.
  /// Allocation-free and noexcept; call it only between StartServo() and StopServo().
  Eigen::Vector3d ServoTick(const DeviceState& state) noexcept;
  /// One tick of a stop (the client is not asked): the force to send, one slew step nearer zero
  /// (ForceAtRest() once it is zero). Allocation-free and noexcept.
  Eigen::Vector3d ServoRampDown() noexcept;
  /// True when the last force sent was zero (on the servo thread, or while no tick runs).
  bool ForceAtRest() const { return safety_->last_output().isZero(0.0); }

 private:
  struct Figures {
    LoopStats loop;
    SafetyCounters safety;
  };
  void PublishFigures();
  Figures LatestFigures() const;

  SafetyOptions safety_options_;
  DeviceSpecs specs_;
  bool open_ = false;
  bool running_ = false;
  ServoClient* client_ = nullptr;
  std::unique_ptr<SafetyLayer> safety_;
  LoopStatsRecorder recorder_;
  std::unique_ptr<TripleBuffer<Figures>> figures_;  // servo thread -> callers of stats()
  mutable std::mutex figures_reader_;               // stats() from several threads
  mutable Figures last_figures_;
};

}  // namespace cosmems
