#pragma once

#include <memory>
#include <string>

#include "cosmems/haptics/haptic_device.hpp"

namespace cosmems {

/// Settings of an OpenHapticsDevice.
struct OpenHapticsOptions {
  /// The device's configured name ("Default Device" for a Touch, "Default PHANToM" for an
  /// Omni); empty asks for HD_DEFAULT_DEVICE, which some driver versions fail to resolve.
  std::string device_name;
  /// Servo rate [Hz]: 500, 1000 or 2000 on every device; FireWire Omnis also accept 1600.
  int scheduler_rate_hz = 1000;
  SafetyOptions safety;
};

/// The most recent error the HD API reported to a device.
struct OpenHapticsError {
  unsigned int code = 0;    ///< HDErrorInfo::errorCode; 0 (HD_SUCCESS) when there was none
  int internal_code = 0;    ///< the driver's own code, for the vendor's support
  std::string description;  ///< hdGetErrorString(code); empty when there was none
};

/// A PHANTOM Omni / Touch (any device of 3D Systems' OpenHaptics HD API). The servo loop is an
/// asynchronous callback on the HD scheduler thread at the highest priority; each tick it reads
/// the stylus in the device frame (converted from mm to m), runs ServoTick() and commands the
/// force in N.
///
/// A force error from the device (warm motors, force above the maximum) marks the next tick's
/// state as a fault: the safety layer drops the force and ramps it in again. A scheduler error
/// (the link failed) ends the loop: servo_ended() turns true and last_error() says why; Stop()
/// then cleans up. The HD scheduler is one per process: Stop() stops it for every device.
///
/// This header needs no OpenHaptics header; the library links the SDK's libHD, or the
/// project's fake of it when the SDK is not installed.
class OpenHapticsDevice final : public HapticDevice {
 public:
  /// Throws std::invalid_argument for a non-positive rate or invalid safety options.
  explicit OpenHapticsDevice(const OpenHapticsOptions& options = {});
  ~OpenHapticsDevice() override;

  /// The most recent HD error of any operation on this device, including the servo loop's.
  /// Callable from any thread.
  OpenHapticsError last_error() const;
  /// True when the servo loop ended on its own (a scheduler error) since the last Start().
  bool servo_ended() const;
  /// True when this library was built against the OpenHaptics SDK, false when against the
  /// project's fake of the HD API.
  static bool BuiltWithSdk();

 protected:
  DeviceStatus OpenBackend(DeviceSpecs& specs) override;
  /// Updates the calibration when the device can do it alone (preferring the automatic, then
  /// the inkwell, then the encoder-reset style). While the loop runs, the loop checks it in its
  /// own frames until it is OK, and this returns what the loop saw last.
  CalibrationStatus CheckCalibration() override;
  DeviceStatus StartServo() override;
  void StopServo() noexcept override;
  void CloseBackend() noexcept override;
  bool Paced() const override { return true; }

 private:
  struct Session;         // HD handles and servo-loop state, defined with the HD headers
  friend struct Session;  // its servo callback calls ServoTick()

  OpenHapticsOptions options_;
  std::unique_ptr<Session> session_;
};

}  // namespace cosmems
