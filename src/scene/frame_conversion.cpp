#include "cosmems/scene/frame_conversion.hpp"

#include <algorithm>

#include "cosmems/scene/scene_conversion.hpp"

namespace cosmems {
namespace {

Material MaterialOf(const Scene& scene, const std::optional<std::string>& name) {
  return EffectiveMaterial(name ? scene.materials.at(*name) : scene.material);
}

int BodyIndex(const StructureDescription& structure, const std::string& name) {
  const auto at = std::find_if(structure.bodies.begin(), structure.bodies.end(),
                               [&](const StructureBody& b) { return b.name == name; });
  return static_cast<int>(at - structure.bodies.begin());
}

}  // namespace

StructureDescription MakeStructureDescription(const Scene& scene) {
  const SceneStructure& s = scene.structure;
  if (s.kind == StructureKind::kFoldedFlexure) {
    FoldedFlexureDesign design = s.folded_flexure;
    design.thickness = s.thickness;
    design.material = EffectiveMaterial(scene.material);
    design.elements = scene.model.elements;
    design.series_order = scene.model.series_order;
    return FoldedFlexure(design);
  }
  StructureDescription out;
  out.series_order = scene.model.series_order;
  for (const SceneNode& node : s.nodes)
    out.nodes.push_back({node.name, node.position, node.anchor});
  for (const SceneBeam& beam : s.beams) {
    StructureMember member;
    member.from = out.FindNode(beam.nodes[0]);
    member.to = out.FindNode(beam.nodes[1]);
    member.material = MaterialOf(scene, beam.material);
    member.section = RectangularSection{beam.width, beam.thickness.value_or(s.thickness)};
    member.elements = beam.elements.value_or(scene.model.elements);
    member.thickness_direction = beam.thickness_direction;
    out.members.push_back(member);
  }
  for (const SceneBody& body : s.bodies) {
    StructureBody b;
    b.name = body.name;
    b.center = body.center;
    b.size = body.size;
    b.density = MaterialOf(scene, body.material).density;
    for (const std::string& name : body.nodes) b.nodes.push_back(out.FindNode(name));
    out.bodies.push_back(b);
  }
  out.Validate();
  return out;
}

FrameLoadCase MakeFrameLoadCase(const Scene& scene, const StructureDescription& structure) {
  FrameLoadCase out;
  for (const ScenePointLoad& p : scene.loads.points) {
    FramePointLoad load;
    if (p.node) load.node = structure.FindNode(*p.node);
    if (p.body) load.body = BodyIndex(structure, *p.body);
    load.force = p.force;
    load.moment = p.moment;
    out.points.push_back(load);
  }
  out.distributed = scene.loads.distributed;
  return out;
}

}  // namespace cosmems
