#pragma once

#include <string>

#include "cosmems/haptics/device_types.hpp"

namespace cosmems {

/// Datasheet figures of the devices the library knows (PHANTOM Omni, Touch, PHANTOM Desktop /
/// Touch X), by model name; an unknown model gets the most conservative of them (the Touch's).
/// Stiffness and damping are the closed-loop values renderable at 1 kHz, well below the
/// mechanism's own stiffness.
DeviceSpecs BuiltInSpecs(const std::string& model);

/// Fills every field a backend left at zero from BuiltInSpecs(reported.model), and holds the
/// force, stiffness and damping to the table's values (a value above them, infinite or NaN is
/// replaced and its name added to reported.bounded_fields; so is a non-finite workspace).
void CompleteSpecs(DeviceSpecs& reported);

}  // namespace cosmems
