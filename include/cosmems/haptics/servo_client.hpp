#pragma once

#include "cosmems/haptics/device_types.hpp"

namespace cosmems {

/// What runs inside the servo loop: once per tick, on the backend's servo thread, it reads the
/// device state and says what force to push with. It must not allocate, lock, block or throw;
/// the safety layer checks and limits whatever it returns before the device sees it.
class ServoClient {
 public:
  virtual ~ServoClient() = default;
  virtual void Tick(const DeviceState& state, ForceCommand& command) noexcept = 0;
  /// Called by HapticDevice::Start() before the first tick: device time starts again at 0, so
  /// whatever the client rendered before must not be taken for fresh.
  virtual void OnStart() noexcept {}
  /// True when Tick() does work of unbounded time (a physics step inside the tick): no watchdog
  /// can see such a tick run late, so a paced device refuses the client (HapticDevice::Start).
  virtual bool BlocksTheTick() const noexcept { return false; }
};

}  // namespace cosmems
