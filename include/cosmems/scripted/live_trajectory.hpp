#pragma once

#include <Eigen/Core>

#include "cosmems/haptics/triple_buffer.hpp"
#include "cosmems/scripted/trajectory.hpp"

namespace cosmems {

/// A script written while it plays: the hand is wherever the newest target put it, so a mouse
/// (or any input polled on another thread) drives the stylus through a ScriptedDevice, which
/// paces, times and guards the ticks exactly as it does for a recorded script. One thread
/// writes with MoveTo(); the servo thread reads the newest target through a wait-free
/// TripleBuffer, so Position() neither locks nor allocates.
class LiveTrajectory final : public Trajectory {
 public:
  /// The hand starts at `start_m` [m, device frame]; the device ticks for `duration_s` (by
  /// default as long as any session lasts: 1e9 s, 32 years). Throws std::invalid_argument for
  /// a start that is not finite or a duration that is not finite and positive.
  explicit LiveTrajectory(const Eigen::Vector3d& start_m, double duration_s = 1e9);

  /// Moves the hand to `position_m` [m, device frame]: the next tick sees it. One writer
  /// thread. A non-finite position reaches the device as it is (the safety layer's business).
  void MoveTo(const Eigen::Vector3d& position_m) { targets_.Publish(position_m); }

  /// The newest target, whatever `t_s`. Called by the one reader: the device's servo thread
  /// (and its Start() before that thread runs).
  Eigen::Vector3d Position(double t_s) const override;
  double Duration() const override { return duration_s_; }

 private:
  // Taking the newest value changes which slot the reader holds, not the script: mutable.
  mutable TripleBuffer<Eigen::Vector3d> targets_;
  double duration_s_;
};

}  // namespace cosmems
