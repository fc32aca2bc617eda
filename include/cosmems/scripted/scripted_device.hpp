#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "cosmems/haptics/haptic_device.hpp"
#include "cosmems/scripted/scripted_options.hpp"
#include "cosmems/scripted/scripted_sample.hpp"
#include "cosmems/scripted/spring_hand.hpp"
#include "cosmems/scripted/trajectory.hpp"

namespace cosmems {

/// A haptic device without hardware: a Trajectory plays the hand, a hand model turns it into
/// stylus motion, and every tick goes through the same ServoTick() (client, safety layer) as a
/// real device. It ticks from 0 to the trajectory's Duration() at specs.nominal_rate_hz, brings
/// the force down to zero along the slew limit (as after Stop()) and then stops by itself; with
/// record on, it keeps every tick, the ramp's too. Storage for the whole run is set up in
/// Start(), so the servo loop allocates nothing.
///
/// Device time is tick / rate on every clock, so runs are reproducible bit for bit; the paced
/// clock only spaces the same ticks out on the wall clock.
class ScriptedDevice : public HapticDevice {
 public:
  /// Throws std::invalid_argument for a null trajectory, a duration that is negative or not
  /// finite, or invalid options.
  explicit ScriptedDevice(std::unique_ptr<const Trajectory> trajectory,
                          const ScriptedOptions& options = {});
  ~ScriptedDevice() override;

  /// Manual clock: runs up to `n` ticks, fewer when the script and the ramp after it end;
  /// returns how many ran (none before Start() or after Stop()). Throws std::logic_error on the
  /// other clocks, whose thread owns the ticks.
  std::uint64_t Step(std::uint64_t n);
  /// True once the whole script has run and the force has come down to zero after it.
  bool Done() const { return done_.load(std::memory_order_acquire); }
  /// Threaded clocks: blocks until the servo thread has ended (script over, or Stop()). Returns at
  /// once on the manual clock or when no thread runs.
  void WaitUntilDone();
  /// Ticks run since Start(), the ramp's included.
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_acquire); }

  /// How the paced clock's thread got on with real-time scheduling (after Start()): what it
  /// obtained, or why not. The other clocks never ask for it.
  const std::string& realtime_note() const { return realtime_note_; }
  const Trajectory& trajectory() const { return *trajectory_; }

  /// The ticks recorded since Start() (none with record off). Safe while the loop runs: every
  /// row returned is complete.
  std::vector<ScriptedSample> Recorded() const;
  /// Writes Recorded() as CSV with the header `time_s,x_m,y_m,z_m,fx_n,fy_n,fz_n`, with enough
  /// digits to read back every double exactly. Throws std::runtime_error naming the file when it
  /// cannot be written.
  void WriteCsv(const std::string& path) const;

 private:
  DeviceStatus OpenBackend(DeviceSpecs& specs) override;
  CalibrationStatus CheckCalibration() override;
  DeviceStatus StartServo() override;
  void StopServo() noexcept override;
  void CloseBackend() noexcept override;
  bool Paced() const override { return options_.clock == ScriptedClock::kPaced; }
  bool Realtime() const override { return realtime_.load(std::memory_order_acquire); }

  /// One servo tick: sample the script, move the hand, run ServoTick(), record.
  void Tick() noexcept;
  void RunPaced() noexcept;
  void RunFast() noexcept;
  /// The servo thread's end: the script and its ramp are over, or a stop found the force at rest.
  bool Finished() const {
    return Done() || (stop_requested_.load(std::memory_order_acquire) && ForceAtRest());
  }

  std::unique_ptr<const Trajectory> trajectory_;
  ScriptedOptions options_;

  // Servo-thread state, set up by StartServo() before the first tick.
  double rate_hz_ = 1000.0;
  std::uint64_t total_ticks_ = 0;
  std::uint64_t tick_ = 0;
  Eigen::Vector3d previous_target_ = Eigen::Vector3d::Zero();
  SpringHand hand_;
  std::vector<ScriptedSample> samples_;

  // Shared with the callers' thread.
  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<bool> done_{false};
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> realtime_{false};
  std::string realtime_note_;  // written before Start() returns
  std::thread thread_;
  std::mutex thread_mutex_;
  std::condition_variable thread_ended_cv_;
  bool thread_ended_ = true;  // guarded by thread_mutex_
};

}  // namespace cosmems
