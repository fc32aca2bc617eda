#pragma once

#include <memory>
#include <string>

#include "cosmems/haptics/haptic_frame.hpp"
#include "cosmems/haptics/haptic_physics.hpp"
#include "cosmems/haptics/loop_stats.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scripted/live_trajectory.hpp"
#include "cosmems/session/haptic_session.hpp"

namespace cosmems::viewer {

/// Where the stylus comes from.
enum class Input {
  kAuto,    ///< an Omni when built with the OpenHaptics SDK and one answers, else the mouse
  kMouse,   ///< the mouse drags the stylus (MouseDevice)
  kScript,  ///< the scene's scripted stylus ([device] trajectory), paced on the wall clock
  kOmni,    ///< a PHANTOM Omni or Touch through the OpenHaptics backend
};

/// "auto" | "mouse" | "script" | "omni".
const char* ToString(Input input);

/// A running haptic session, as the display sees it: the newest frame, the
/// "Reset Failure" request, the device's figures and, with the mouse, the live hand.
class ViewerSession {
 public:
  /// Opens the device for `input` (kAuto resolved), builds the session from `scene` with the
  /// physics `physics` and starts it. Throws what opening or starting throws, naming the
  /// setting.
  static std::unique_ptr<ViewerSession> Start(const Scene& scene, Input input,
                                              const HapticPhysicsOptions& physics);
  virtual ~ViewerSession() = default;

  /// Takes the newest frame; true when it changed. Display thread only.
  virtual bool UpdateFrame() = 0;
  virtual const HapticFrame& frame() const = 0;
  /// The paper's "Reset Failure", from the display thread.
  virtual void RequestReset() = 0;
  /// Stops the servo loop and the physics; the figures are complete afterwards.
  virtual void Stop() = 0;
  /// HapticSession::DeviceAlert(). When the servo loop ended on its own (a device's scheduler
  /// failed), the session is stopped here too (motors off, physics joined), and the alert stays.
  virtual std::string DeviceAlert() = 0;
  virtual const OpenedDevice& opened() const = 0;
  virtual int dofs() const = 0;
  /// The physics thread's tick times: complete only after Stop().
  virtual const LoopStats& physics_stats() const = 0;
  virtual std::uint64_t failed_ticks() const = 0;

  /// The input the session runs (never kAuto).
  Input input() const { return input_; }
  /// The live hand the mouse moves (null for the other inputs).
  LiveTrajectory* hand() const { return hand_; }
  /// How the session came to its input (e.g. why not an Omni); empty when as asked.
  const std::string& input_note() const { return input_note_; }

 protected:
  Input input_ = Input::kMouse;
  LiveTrajectory* hand_ = nullptr;
  std::string input_note_;
};

}  // namespace cosmems::viewer
