#pragma once

#include "cosmems/analysis/frame_record_point.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The point the built-in motions press and the haptic displays follow: the node or body named
/// by device.target, else the structure's first watched point (MakeFrameRecord: a cantilever's
/// tip, a bridge's midspan, a device's first body). Throws std::invalid_argument naming
/// device.target when the target names nothing or the structure offers no point.
FrameRecordPoint TouchTarget(const Scene& scene, const StructureDescription& structure);

}  // namespace cosmems
