#pragma once

#include "cosmems/scene/scene.hpp"
#include "cosmems/scripted/live_trajectory.hpp"
#include "cosmems/session/haptic_session.hpp"

namespace cosmems::viewer {

/// The stylus when no haptic device is present: the mouse moves a LiveTrajectory that a paced
/// ScriptedDevice plays, so the mouse reaches the beam through the same interface, servo loop,
/// safety layer and figures as a PHANTOM Omni.
struct MouseDevice {
  OpenedDevice opened;
  /// The live script, owned by the device: the display thread moves it.
  LiveTrajectory* hand = nullptr;
};

/// Opens the mouse's device for `scene`: the scripted stylus's specs and settings, the hand
/// resting where the scene's script starts (above the tip or the midspan, clear of the beam),
/// one tick a period on the wall clock, nothing recorded.
MouseDevice OpenMouseDevice(const Scene& scene);

}  // namespace cosmems::viewer
