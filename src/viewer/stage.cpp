#include "stage.hpp"

#include <algorithm>

#include "cosmems/scene/frame_conversion.hpp"
#include "device_stage.hpp"

namespace cosmems::viewer {

Stage BuildStage(const Scene& scene, const DisplaySpace& space) {
  if (IsDevice(scene.structure.kind)) {
    return BuildDeviceStage(scene, MakeStructureDescription(scene), space);
  }
  const SceneStructure& s = scene.structure;
  const double length = s.length, width = s.width, half_t = 0.5 * s.thickness;
  // How far the substrate's slab goes down, and the supports' blocks reach along x [m].
  const double base = std::max(s.thickness, 0.02 * length);
  const double block = 0.08 * length;
  const double floor = -half_t - s.gap.value_or(s.thickness) - base;
  Stage stage;
  auto box = [&](Mesh& mesh, const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
    mesh.AddBox(space.ToWorld(low), space.ToWorld(high));
  };
  // The supports hold the section's full height and stand on the substrate (or its place).
  box(stage.supports, {-block, floor, -0.75 * width}, {0.0, half_t, 0.75 * width});
  if (s.kind == StructureKind::kBridge) {
    box(stage.supports, {length, floor, -0.75 * width}, {length + block, half_t, 0.75 * width});
  }
  if (!s.gap) return stage;
  const double top = -half_t - *s.gap;
  box(stage.substrate, {-0.15 * length, top - base, -3.0 * width},
      {1.15 * length, top, 3.0 * width});
  const std::optional<ElectrostaticEffect>& electrode = scene.effects.electrostatic;
  if (IsOn(electrode)) {
    // A pad a fiftieth of the gap thick, just wider than the beam.
    box(stage.electrode, {electrode->electrode_start.value_or(0.0), top, -0.6 * width},
        {electrode->electrode_end.value_or(length), top + 0.02 * *s.gap, 0.6 * width});
  }
  return stage;
}

void BuildStylus(const Eigen::Vector3d& probe_m, double radius_m, double length_m,
                 const DisplaySpace& space, Mesh& mesh) {
  mesh.Clear();
  const Eigen::Vector3d radii(1e6 * radius_m, 1e6 * radius_m * space.exaggeration, 1e6 * radius_m);
  const Eigen::Vector3d centre = space.ToWorld(probe_m);
  mesh.AddEllipsoid(centre, radii);
  const double half = 0.3 * radii.x();
  const Eigen::Vector3d top = centre + Eigen::Vector3d(0.0, 0.8 * radii.y(), 0.0);
  mesh.AddBox(top - Eigen::Vector3d(half, 0.0, half),
              top + Eigen::Vector3d(half, 1e6 * length_m, half));
}

OrbitCamera DefaultCamera(const Scene& scene, const DisplaySpace& space) {
  if (IsDevice(scene.structure.kind)) return DeviceCamera(MakeStructureDescription(scene), space);
  const double length = scene.structure.length;
  const Eigen::Vector3d target = space.ToWorld(Eigen::Vector3d(0.55 * length, 0.0, 0.0));
  return OrbitCamera(target, 1.6e6 * length, 0.5, 0.3);
}

}  // namespace cosmems::viewer
