#pragma once

#include <atomic>
#include <chrono>
#include <cmath>
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
  /// Inside each servo tick: deterministic, the tick pays for the physics and nothing watches
  /// its time, so only for devices that are not paced (a script run as fast as possible); a
  /// paced device refuses it (DeviceStatus::kRefused).
  kServo,
  /// Its own thread, paced at the physics tick; the servo loop renders its LocalModel, whose age
  /// in wall time the safety layer watches (a stalled physics tick brings the force to zero).
  kOwn,
};

struct HapticLoopOptions {
  HandScaling scaling;
  PhysicsThread physics = PhysicsThread::kOwn;
  /// The stylus button (bit index) whose press is the paper's "Reset Failure"; -1: none.
  int reset_button = 1;
};

/// The ServoClient that lets a hand touch a HapticPhysics (a beam or any structure): each servo
/// tick maps the stylus into the micro world (HandScaling), has the physics place the probe there
/// (in the tick, or on the physics thread through a TripleBuffer), renders the probe's force from
/// the newest LocalModel and scales it back to the hand. The display side reads HapticFrames
/// through another TripleBuffer. Tick() allocates nothing. A physics tick that fails, throws
/// (a reset that cannot allocate) or gives a non-finite model counts as failed, and its model is
/// invalid until the next good one.
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
      // Made within this tick of device time: age 0 (only unpaced devices take this path).
      RunPhysicsTick({micro, state.time_s, state.buttons});
      model_ = made_;
      command.age_s = 0.0;
    } else {
      probes_.Publish({micro, state.time_s, state.buttons});
      if (models_.Update()) model_ = models_.Front();
      // Wall time, not device ticks: a servo thread that itself stalled, or a device clock that
      // runs faster than the wall, would otherwise see a stalled physics thread's model as new.
      command.age_s = Now() - model_.made_s;
    }
    command.valid = model_.model.valid;
    command.force_n = options_.scaling.HandForce(model_.model.ForceAt(micro));
  }

  /// True with the physics inside the tick: a paced device refuses the loop then.
  bool BlocksTheTick() const noexcept override { return options_.physics == PhysicsThread::kServo; }

  /// Forgets the model rendered before a device (re)start: it answered the hand of the run
  /// before.
  void OnStart() noexcept override { model_ = MadeModel{}; }

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
  // A local model and the wall time at which the physics tick that made it began.
  struct MadeModel {
    LocalModel model;
    double made_s = 0.0;
  };
  // Every number the servo renders from: a NaN stiffness or normal would turn into a NaN force
  // (caught by the safety layer, but as the physics' failure, which it is).
  static bool Finite(const LocalModel& m) {
    return m.probe_m.allFinite() && m.normal.allFinite() && std::isfinite(m.force_n) &&
           std::isfinite(m.stiffness_n_per_m) && std::isfinite(m.clearance_m);
  }

  static HapticLoopOptions ValidOptions(const HapticLoopOptions& options) {
    options.scaling.Validate();
    return options;
  }

  static double Now() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
  }

  void RunPhysicsTick(const ProbeInput& input) noexcept {
    const double start = Now();
    const bool reset = options_.reset_button >= 0 &&
                       ((input.buttons >> options_.reset_button) & 1u) != 0 &&
                       ((last_buttons_ >> options_.reset_button) & 1u) == 0;
    last_buttons_ = input.buttons;
    // Both sources are consumed every tick, so a request and a press together reset once.
    const bool requested = reset_requested_.exchange(false, std::memory_order_acq_rel);
    bool ok = false;
    try {
      // A reset may allocate (HapticPhysics::Reset); on either thread nothing may escape.
      if (reset || requested) touched_.Reset();
      ok = touched_.Advance(input.probe_m, input.time_s) == Status::kOk;
    } catch (...) {
      ok = false;
    }
    made_.model = touched_.local_model();
    made_.made_s = start;
    if (!ok || !Finite(made_.model)) {
      made_.model.valid = false;
      ++failed_;
    }
    touched_.Fill(frames_.Back());
    frames_.Publish();
    physics_.Record(start, (Now() - start) * 1e6);
  }

  // The physics thread: one tick a period on absolute deadlines (no drift, no busy wait), on the
  // newest probe position the servo loop published. After a stall it does not run the missed
  // ticks back to back: each would compute on the same newest probe, and keep the servo's
  // model old for as long.
  void RunPhysics() {
    PeriodicDeadline deadline(1.0 / touched_.tick_s(), CatchUp::kSkip);
    ProbeInput input;
    while (!stop_.load(std::memory_order_relaxed)) {
      if (probes_.Update()) input = probes_.Front();
      RunPhysicsTick(input);
      models_.Publish(made_);
      deadline.SleepUntilNext();
    }
  }

  HapticPhysics& touched_;
  HapticLoopOptions options_;
  MadeModel made_;   // the physics tick's (either thread's)
  MadeModel model_;  // the servo thread's copy
  std::uint32_t last_buttons_ = 0;
  std::uint64_t failed_ = 0;
  LoopStatsRecorder physics_;
  TripleBuffer<ProbeInput> probes_;   // servo -> physics
  TripleBuffer<MadeModel> models_;    // physics -> servo
  TripleBuffer<HapticFrame> frames_;  // physics -> display
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> reset_requested_{false};  // any thread -> the physics tick
};

}  // namespace cosmems
