#pragma once

#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "toml_field_reader.hpp"

namespace cosmems::internal {

// What a device's netlist must be for its model to be built and solved, checked on the
// description (MakeStructureDescription) before any model is: each failure is a SceneError
// naming the key that made it.

/// Its model fits the limits of scene_limits.hpp: the elements of all its members, then the
/// memory its band matrices and elements would take.
void CheckDeviceSize(const TomlFieldReader& r, const Scene& scene,
                     const StructureDescription& structure);

/// Every connected part of a frame's netlist is held by its supports (FindFloatingPart); the
/// part that floats is named at structure.nodes.
void CheckFrameSupports(const TomlFieldReader& r, const StructureDescription& structure);

}  // namespace cosmems::internal
