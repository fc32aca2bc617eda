#pragma once

#include <memory>

#include "cosmems/haptics/device_types.hpp"
#include "cosmems/haptics/hand_scaling.hpp"
#include "cosmems/haptics/probe_contact.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scripted/trajectory.hpp"

namespace cosmems::internal {

/// How a haptic scene's hand meets its beam: the scaling, the probe and the stylus's script,
/// from [device] with the defaults SCENES.md documents.
struct HapticSettings {
  HandScaling scaling;
  ProbeOptions probe;
  std::unique_ptr<Trajectory> trajectory;
  DeviceSpecs specs;              ///< the scripted device's (a PHANTOM Omni at the scene's rate)
  double felt_coupling_n_per_m;   ///< the coupling as the hand feels it
  double felt_structure_n_per_m;  ///< the free structure at the probe as the hand feels it
};

/// Derives the settings. The probe starts one gap (or one thickness without a substrate) above
/// the beam's upper face over the cantilever's tip or the bridge's midspan; the built-in motions
/// press 2.2 of those distances down (through the clearance, the gap, then a little into the
/// contact). Throws CliInputError naming a [device] key whose value the device cannot render.
HapticSettings MakeHapticSettings(const Scene& scene);

}  // namespace cosmems::internal
