#include "device_stage.hpp"

#include <algorithm>
#include <limits>

#include "comb_mesh.hpp"
#include "cosmems/scene/frame_conversion.hpp"

namespace cosmems::viewer {

Footprint FootprintOf(const StructureDescription& structure) {
  Footprint f;
  f.low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  f.high = -f.low;
  f.lowest_face_m = std::numeric_limits<double>::infinity();
  auto cover = [&](const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
    f.low = f.low.cwiseMin(low);
    f.high = f.high.cwiseMax(high);
  };
  for (const StructureMember& m : structure.members) {
    for (int n : {m.from, m.to}) {
      const Eigen::Vector3d& p = structure.nodes[n].position;
      cover(p, p);
      f.lowest_face_m = std::min(f.lowest_face_m, p.y() - 0.5 * m.section.thickness);
    }
  }
  for (const StructureBody& b : structure.bodies) {
    cover(b.center - 0.5 * b.size, b.center + 0.5 * b.size);
    f.lowest_face_m = std::min(f.lowest_face_m, b.center.y() - 0.5 * b.size.y());
  }
  return f;
}

Stage BuildDeviceStage(const Scene& scene, const StructureDescription& structure,
                       const DisplaySpace& space) {
  const Footprint f = FootprintOf(structure);
  const double extent = f.Extent(), margin = 0.15 * extent;
  const double thickness = scene.structure.thickness, base = std::max(thickness, 0.02 * extent);
  const double top = f.lowest_face_m - scene.structure.gap.value_or(thickness);
  Stage stage;
  auto box = [&](Mesh& mesh, const Eigen::Vector3d& low, const Eigen::Vector3d& high) {
    mesh.AddBox(space.ToWorld(low), space.ToWorld(high));
  };
  // An anchor six times as wide as its widest member, as high as its thickest.
  for (std::size_t n = 0; n < structure.nodes.size(); ++n) {
    const StructureNode& node = structure.nodes[n];
    if (std::none_of(node.anchor.begin(), node.anchor.end(), [](bool fixed) { return fixed; })) {
      continue;
    }
    double width = 0.0, half_t = 0.5 * thickness;
    for (const StructureMember& m : structure.members) {
      if (m.from != static_cast<int>(n) && m.to != static_cast<int>(n)) continue;
      width = std::max(width, m.section.width);
      half_t = std::max(half_t, 0.5 * m.section.thickness);
    }
    const double half = 3.0 * std::max(width, thickness);
    const Eigen::Vector3d& p = node.position;
    box(stage.supports, {p.x() - half, top, p.z() - half},
        {p.x() + half, p.y() + half_t, p.z() + half});
  }
  for (const CombDrive& comb : MakeCombDrives(scene, structure)) {
    AddCombFingers(comb, structure.bodies[comb.body], CombHalf::kFixed,
                   Eigen::Matrix<double, 6, 1>::Zero(), space, stage.supports);
  }
  if (!scene.structure.gap) return stage;
  box(stage.substrate, {f.low.x() - margin, top - base, f.low.z() - margin},
      {f.high.x() + margin, top, f.high.z() + margin});
  if (IsOn(scene.effects.electrostatic)) {
    // Pads a fiftieth of the gap thick.
    const double pad = top + 0.02 * *scene.structure.gap;
    const std::vector<SceneElectrode>& rectangles = scene.effects.electrostatic->electrodes;
    if (rectangles.empty())
      box(stage.electrode, {f.low.x(), top, f.low.z()}, {f.high.x(), pad, f.high.z()});
    for (const SceneElectrode& r : rectangles) {
      box(stage.electrode, {r.x[0], top, r.z[0]}, {r.x[1], pad, r.z[1]});
    }
  }
  return stage;
}

OrbitCamera DeviceCamera(const StructureDescription& structure, const DisplaySpace& space) {
  const Footprint f = FootprintOf(structure);
  const Eigen::Vector3d centre = 0.5 * (f.low + f.high);
  return OrbitCamera(space.ToWorld(Eigen::Vector3d(centre.x(), 0.0, centre.z())),
                     2.2e6 * f.Extent(), 0.5, 0.5);
}

}  // namespace cosmems::viewer
