#pragma once

#include <memory>
#include <string>

#include "cosmems/haptics/haptic_device.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/haptics/haptic_physics.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/session/haptic_settings.hpp"

namespace cosmems {
class OpenHapticsDevice;
class ScriptedDevice;
}  // namespace cosmems

namespace cosmems {

/// A haptic device, open, with the settings derived from its specs.
struct OpenedDevice {
  std::unique_ptr<HapticDevice> device;
  ScriptedDevice* scripted = nullptr;        ///< the same device when scripted
  OpenHapticsDevice* openhaptics = nullptr;  ///< the same device when an OpenHaptics one
  HapticSettings settings;
  /// The ticks follow the wall clock (a paced script, a real device's scheduler): the physics
  /// then runs on its own thread; otherwise inside each servo tick, deterministically.
  bool paced = false;
};

/// The device a scene's [device] asks for, open: a ScriptedDevice replaying its trajectory
/// (paced when realtime = true) or an OpenHapticsDevice at the scene's rate. Throws
/// std::runtime_error naming device.backend when the device does not open,
/// std::invalid_argument for settings the device cannot render.
OpenedDevice OpenDevice(const Scene& scene);

/// One touch of a scene's structure, built the same way for every program: the model of the
/// scene (a beam numbered node by node in 3-D, so that a press off the axis twists it; or a
/// device's frame), the effects it declares, the HapticPhysics with the probe, and the
/// HapticLoop the device's servo thread ticks. Start() runs it, Stop() (or the destructor) ends
/// it; the parts stay readable after Stop() for the figures.
class HapticSession {
 public:
  /// `device` must be open. `physics` sets the substeps and rho_inf; its tick is the period of
  /// the scene's analysis.rate, and the scene's analysis.integrator = "modal" sets its modal
  /// path (model.modes, damped by effects.damping).
  HapticSession(const Scene& scene, OpenedDevice device, HapticPhysicsOptions physics = {});
  ~HapticSession();
  HapticSession(const HapticSession&) = delete;
  HapticSession& operator=(const HapticSession&) = delete;

  /// Starts the physics thread (paced devices) and the servo loop. Throws std::runtime_error
  /// naming device.backend when the loop does not start.
  void Start();
  /// Stops the servo loop, then the physics thread; idempotent. The device stays open.
  void Stop();

  /// What the person at the device must be told now, empty when nothing: the servo loop ended
  /// on its own (the device's scheduler failed; its motors are off, Stop() cleans up), or the
  /// forces are held off until the device is calibrated. Any thread but the servo thread.
  std::string DeviceAlert();
  /// The first of DeviceAlert()'s: empty unless the servo loop ended on its own.
  std::string ServoFault() const;

  HapticDevice& device() { return *opened_.device; }
  const OpenedDevice& opened() const { return opened_; }
  const HapticSettings& settings() const { return opened_.settings; }
  const HapticPhysics& physics() const;
  HapticLoop& loop() { return loop_; }
  const HapticLoop& loop() const { return loop_; }

  /// What the session touches: the scene's structure, its effects and its physics (defined
  /// where the session is built).
  struct Touched;

 private:
  OpenedDevice opened_;
  std::unique_ptr<Touched> touched_;
  HapticLoop loop_;
};

}  // namespace cosmems
