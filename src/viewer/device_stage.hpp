#pragma once

#include <Eigen/Core>

#include "camera.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "display_space.hpp"
#include "stage.hpp"

namespace cosmems::viewer {

/// Where a device stands at rest: the box its members' axes and its bodies fill [m] and the
/// height of its lowest face, which the substrate lies `structure.gap` below.
struct Footprint {
  Eigen::Vector3d low = Eigen::Vector3d::Zero(), high = Eigen::Vector3d::Zero();
  double lowest_face_m = 0.0;

  /// The longer side in the substrate's plane [m].
  double Extent() const { return std::max(high.x() - low.x(), high.z() - low.z()); }
};

Footprint FootprintOf(const StructureDescription& structure);

/// What stands still around a device, in the world of `space`: the substrate (a slab the gap
/// below the lowest face, reaching 15 % of the device's extent past its footprint), a block
/// under each anchored node from the substrate up to the node's upper face, the electrodes on
/// the substrate (the scene's rectangles, or one under all the device) and the combs' fixed
/// fingers. Without a gap the anchors stand on the substrate's place and there is no substrate
/// and no electrode.
Stage BuildDeviceStage(const Scene& scene, const StructureDescription& structure,
                       const DisplaySpace& space);

/// The view of a device: from above, in front of the footprint's centre, all of it in sight.
OrbitCamera DeviceCamera(const StructureDescription& structure, const DisplaySpace& space);

}  // namespace cosmems::viewer
