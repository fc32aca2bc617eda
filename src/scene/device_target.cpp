#include "cosmems/scene/device_target.hpp"

namespace cosmems {

std::string DeviceTarget(const Scene& scene, const StructureDescription& structure) {
  if (scene.device && scene.device->target) return *scene.device->target;
  return structure.bodies.empty() ? std::string() : structure.bodies.front().name;
}

}  // namespace cosmems
