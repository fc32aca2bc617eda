#pragma once

#include <string>

#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The node or body the built-in motions press on a device: the scene's device.target, or the
/// structure's first body (empty when it has none).
std::string DeviceTarget(const Scene& scene, const StructureDescription& structure);

}  // namespace cosmems
