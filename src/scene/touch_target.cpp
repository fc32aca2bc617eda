#include "cosmems/scene/touch_target.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/scene/frame_conversion.hpp"

namespace cosmems {

FrameRecordPoint TouchTarget(const Scene& scene, const StructureDescription& structure) {
  if (scene.device && scene.device->target) {
    const std::string& target = *scene.device->target;
    const int node = structure.FindNode(target);
    const int body = node >= 0 ? -1 : structure.FindBody(target);
    if (node < 0 && body < 0) {
      throw std::invalid_argument("device.target: no node or body \"" + target + "\"");
    }
    return {node, body};
  }
  const std::vector<FrameRecordPoint> watched = MakeFrameRecord(scene, structure);
  if (watched.empty()) {
    throw std::invalid_argument("device.target: the structure has no body; name the node to press");
  }
  return watched.front();
}

}  // namespace cosmems
