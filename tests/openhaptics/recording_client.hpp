#pragma once

#include <atomic>
#include <cstdint>

#include "cosmems/haptics/servo_client.hpp"

namespace cosmems {

/// Asks for a constant force and keeps the last state it was shown.
class RecordingClient : public ServoClient {
 public:
  explicit RecordingClient(const Eigen::Vector3d& force_n = Eigen::Vector3d::Zero())
      : force_n_(force_n) {}

  void Tick(const DeviceState& state, ForceCommand& command) noexcept override {
    last_ = state;
    ticks_.fetch_add(1, std::memory_order_relaxed);
    command.force_n = force_n_;
  }

  /// Read only while the loop is stopped, or between manual ticks.
  const DeviceState& last() const { return last_; }
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_relaxed); }

 private:
  Eigen::Vector3d force_n_;
  DeviceState last_;
  std::atomic<std::uint64_t> ticks_{0};
};

}  // namespace cosmems
