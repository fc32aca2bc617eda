#pragma once

#include <Eigen/Core>

#include "camera.hpp"
#include "cosmems/scene/scene.hpp"
#include "display_space.hpp"
#include "mesh.hpp"

namespace cosmems::viewer {

/// What stands still around the beam, in the world of `space`: the substrate (a slab whose top
/// is the gap below the beam's lower face, reaching 15 % of the length past each end and three
/// widths to each side), the supports (a block under each clamped end) and the electrode (a
/// pad on the substrate over its span, when the scene declares one). Without a gap there is no
/// substrate and no electrode. A device's stage is BuildDeviceStage's.
struct Stage {
  Mesh substrate;
  Mesh supports;
  Mesh electrode;
};

Stage BuildStage(const Scene& scene, const DisplaySpace& space);

/// The stylus: the probe's sphere at `probe_m` [m, beam axes] (stretched along y like the rest)
/// on a shaft rising from it.
void BuildStylus(const Eigen::Vector3d& probe_m, double radius_m, double length_m,
                 const DisplaySpace& space, Mesh& mesh);

/// The view the viewer opens with, and always uses headless: from above the substrate, in
/// front of the beam and a little past its far end, the whole beam and stage in sight (a
/// device's: DeviceCamera).
OrbitCamera DefaultCamera(const Scene& scene, const DisplaySpace& space);

}  // namespace cosmems::viewer
