#pragma once

#include <string>
#include <vector>

#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// Warnings for settings that the scene's analysis accepts but does not use, where a reader
/// could expect them to matter: [effects.damping], model.modes > 0 and loads.time_function in an
/// analysis without time (they act in transient analyses only); [loads], [effects.damping] and
/// loads.time_function in a haptic analysis (the probe is its only load); [device] in any
/// analysis but the haptic one.
std::vector<std::string> IgnoredSettingWarnings(const Scene& scene);

}  // namespace cosmems::internal
