#pragma once

#include <memory>

#include "cosmems/haptics/device_types.hpp"
#include "cosmems/haptics/hand_scaling.hpp"
#include "cosmems/haptics/probe_faces.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scripted/trajectory.hpp"

namespace cosmems {

/// How a haptic scene's hand meets its structure: the scaling, the probe and the stylus's script,
/// from [device] with the defaults doc/scenes.md documents.
struct HapticSettings {
  HandScaling scaling;
  ProbeOptions probe;
  std::unique_ptr<Trajectory> trajectory;  ///< the scripted stylus's (null for a real device)
  DeviceSpecs specs;                       ///< the device's
  double felt_coupling_n_per_m;            ///< the coupling as the hand feels it
  double felt_structure_n_per_m;           ///< the free structure at the probe as the hand feels it
};

/// The scripted stylus's device: a PHANTOM Omni at the scene's rate.
DeviceSpecs ScriptedSpecs(const Scene& scene);

/// Derives the settings for a device with `specs`. The probe starts one gap (or one thickness
/// without a substrate) above the upper face of the pressed point (a cantilever's tip, a bridge's
/// midspan, or a device's device.target: a body's centre, a node), where the device's frame has the
/// point half a press above its origin; the built-in motions press 2.2 of those distances down
/// (through the clearance, the gap, then a little into the contact). The trajectory is made for the
/// scripted backend only. Throws std::invalid_argument naming a [device] key whose value the device
/// cannot render (or, for device.target, a point that does not move).
HapticSettings MakeHapticSettings(const Scene& scene, const DeviceSpecs& specs);

}  // namespace cosmems
