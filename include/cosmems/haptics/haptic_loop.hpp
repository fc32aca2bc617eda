#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <thread>

#include "cosmems/haptics/hand_scaling.hpp"
#include "cosmems/haptics/haptic_physics.hpp"
#include "cosmems/haptics/loop_stats.hpp"
#include "cosmems/haptics/periodic_deadline.hpp"
#include "cosmems/haptics/servo_client.hpp"
#include "cosmems/haptics/triple_buffer.hpp"

namespace cosmems {

/// Where the physics runs relative to the servo loop.
enum class PhysicsThread {
  kServo,  ///< inside each servo tick: deterministic, the tick pays for the physics
  kOwn,    ///< its own thread, paced at the physics tick; the servo loop renders its LocalModel
};

struct HapticLoopOptions {
  HandScaling scaling;
  PhysicsThread physics = PhysicsThread::kServo;
  /// The stylus button (bit index) whose press is the paper's "Reset Failure"; -1: none.
  int reset_button = 1;
};

/// The ServoClient that lets a hand touch a HapticPhysics (a beam or any structure): each servo
/// tick maps the stylus into the micro world (HandScaling), has the physics place the probe there
/// (in the tick, or on the physics thread through a TripleBuffer), renders the probe's force from
/// the newest LocalModel and scales it back to the hand. The display side reads HapticFrames
/// through another TripleBuffer. Tick() allocates nothing.
class HapticLoop final : public ServoClient {
 public:
  HapticLoop(HapticPhysics& physics, const HapticLoopOptions& options)
      : touched_(physics), options_(ValidOptions(options)), frames_(physics.MakeFrame()) {
    physics_.Start(physics.tick_s(), options.physics == PhysicsThread::kOwn, false);
  }
  ~HapticLoop() override { StopPhysics(); }
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  /// Starts the physics thread (PhysicsThread::kOwn; nothing otherwise), one physics tick a
  /// period. Before the device.
  void StartPhysics() {
    if (options_.physics != PhysicsThread::kOwn || thread_.joinable()) return;
    physics_.Start(touched_.tick_s(), true, false);
    stop_ = false;
    thread_ = std::thread([this] { RunPhysics(); });
  }
  /// Stops and joins the physics thread (after the device has stopped).
  void StopPhysics() {
    if (!thread_.joinable()) return;
    stop_ = true;
    thread_.join();
  }

  void Tick(const DeviceState& state, ForceCommand& command) noexcept override {
    const Eigen::Vector3d micro = options_.scaling.ToMicro(state.position_m);
    if (options_.physics == PhysicsThread::kServo) {
      RunPhysicsTick({micro, state.time_s, state.buttons});
      model_ = touched_.local_model();
    } else {
      probes_.Publish({micro, state.time_s, state.buttons});
      if (models_.Update()) model_ = models_.Front();
    }
    command.valid = model_.valid;
    command.age_s = state.time_s - model_.source_time_s;
    command.force_n = options_.scaling.HandForce(model_.ForceAt(micro));
  }

  /// Forgets the model rendered before a device (re)start: its source time is on the old
  /// device clock, which starts again at 0.
  void OnStart() noexcept override { model_ = LocalModel{}; }

  /// The paper's "Reset Failure" asked for from any thread (a button on the display side): the
  /// next physics tick resets the structure, as the stylus button does. Wait-free.
  void RequestReset() { reset_requested_.store(true, std::memory_order_release); }

  /// Display side (one thread): takes the newest frame, true when it changed.
  bool UpdateFrame() { return frames_.Update(); }
  const HapticFrame& frame() const { return frames_.Front(); }

  /// Physics tick times (the servo loop's own figures come from the device); complete once the
  /// device and the physics thread have stopped.
  const LoopStats& physics_stats() const { return physics_.stats(); }
  /// Ticks whose physics failed (the local model was invalid until the next good one).
  std::uint64_t failed_ticks() const { return failed_; }

 private:
  struct ProbeInput {
    Eigen::Vector3d probe_m = Eigen::Vector3d(0.0, 1.0, 0.0);
    double time_s = 0.0;
    std::uint32_t buttons = 0;
  };

  static HapticLoopOptions ValidOptions(const HapticLoopOptions& options) {
    options.scaling.Validate();
    return options;
  }

  static double Now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }

  void RunPhysicsTick(const ProbeInput& input) {
    const double start = Now();
    const bool reset = options_.reset_button >= 0 &&
                       ((input.buttons >> options_.reset_button) & 1u) != 0 &&
                       ((last_buttons_ >> options_.reset_button) & 1u) == 0;
    last_buttons_ = input.buttons;
    // Both sources are consumed every tick, so a request and a press together reset once.
    const bool requested = reset_requested_.exchange(false, std::memory_order_acq_rel);
    if (reset || requested) touched_.Reset();
    if (touched_.Advance(input.probe_m, input.time_s) != Status::kOk) ++failed_;
    touched_.Fill(frames_.Back());
    frames_.Publish();
    physics_.Record(start, (Now() - start) * 1e6);
  }

  // The physics thread: one tick a period on absolute deadlines (no drift, no busy wait), on the
  // newest probe position the servo loop published.
  void RunPhysics() {
    PeriodicDeadline deadline(1.0 / touched_.tick_s());
    ProbeInput input;
    while (!stop_.load(std::memory_order_relaxed)) {
      if (probes_.Update()) input = probes_.Front();
      RunPhysicsTick(input);
      models_.Publish(touched_.local_model());
      deadline.SleepUntilNext();
    }
  }

  HapticPhysics& touched_;
  HapticLoopOptions options_;
  LocalModel model_;  // the servo thread's copy
  std::uint32_t last_buttons_ = 0;
  std::uint64_t failed_ = 0;
  LoopStatsRecorder physics_;
  TripleBuffer<ProbeInput> probes_;   // servo -> physics
  TripleBuffer<LocalModel> models_;   // physics -> servo
  TripleBuffer<HapticFrame> frames_;  // physics -> display
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> reset_requested_{false};  // any thread -> the physics tick
};

}  // namespace cosmems
