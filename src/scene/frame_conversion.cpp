#include "cosmems/scene/frame_conversion.hpp"

#include <algorithm>
#include <cmath>

#include "cosmems/scene/scene_conversion.hpp"

namespace cosmems {
namespace {

Material MaterialOf(const Scene& scene, const std::optional<std::string>& name) {
  return EffectiveMaterial(name ? scene.materials.at(*name) : scene.material);
}

// A parametric device's netlist: its design keys, with the members' thickness, material,
// elements and series order from structure.thickness, [material] and [model].
template <class Design>
StructureDescription Generate(Design design, const Scene& scene,
                              StructureDescription (*generator)(const Design&)) {
  design.thickness = scene.structure.thickness;
  design.material = EffectiveMaterial(scene.material);
  design.elements = scene.model.elements;
  design.series_order = scene.model.series_order;
  return generator(design);
}

}  // namespace

StructureDescription MakeStructureDescription(const Scene& scene) {
  const SceneStructure& s = scene.structure;
  switch (s.kind) {
    case StructureKind::kFoldedFlexure:
      return Generate(s.folded_flexure, scene, &FoldedFlexure);
    case StructureKind::kCrabLeg:
      return Generate(s.crab_leg, scene, &CrabLeg);
    case StructureKind::kSerpentine:
      return Generate(s.serpentine, scene, &Serpentine);
    case StructureKind::kTorsionalMicromirror:
      return Generate(s.torsional_micromirror, scene, &TorsionalMicromirror);
    case StructureKind::kAccelerometer:
      return Generate(s.accelerometer, scene, &Accelerometer);
    case StructureKind::kCantilever:
    case StructureKind::kBridge: {
      StraightBeamDesign beam;
      beam.bridge = s.kind == StructureKind::kBridge;
      beam.length = s.length;
      beam.material = EffectiveMaterial(scene.material);
      beam.section = RectangularSection{s.width, s.thickness};
      beam.elements = scene.model.elements;
      beam.series_order = scene.model.series_order;
      beam.axial_load = s.axial_load;
      beam.planar = scene.model.dimension == 2;
      return StraightBeam(beam);
    }
    case StructureKind::kFrame:
      break;  // a frame's netlist is written out, below
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

bool IsStraightBeam(const Scene& scene) {
  return scene.structure.kind == StructureKind::kCantilever ||
         scene.structure.kind == StructureKind::kBridge;
}

FrameCouplings MakeFrameCouplings(const Scene& scene) {
  return scene.model.theory == Theory::kStretching ? FrameCouplings::kStretching
                                                   : FrameCouplings::kLinear;
}

FrameLoadCase MakeFrameLoadCase(const Scene& scene, const StructureDescription& structure) {
  FrameLoadCase out;
  for (const ScenePointLoad& p : scene.loads.points) {
    FramePointLoad load;
    if (p.node) load.node = structure.FindNode(*p.node);
    if (p.body) load.body = structure.FindBody(*p.body);
    load.force = p.force;
    load.moment = p.moment;
    out.points.push_back(load);
  }
  // A beam's loads: the tip's at its node "tip", the midspan force halfway along its member.
  const SceneLoads& beam = scene.loads;
  if (!beam.tip_force.isZero(0.0) || !beam.tip_moment.isZero(0.0)) {
    FramePointLoad tip;
    tip.node = structure.FindNode("tip");
    tip.force = beam.tip_force;
    tip.moment = beam.tip_moment;
    out.points.push_back(tip);
  }
  if (!beam.midspan_force.isZero(0.0)) {
    FramePointLoad midspan;
    midspan.member = 0;
    midspan.at = 0.5;
    midspan.force = beam.midspan_force;
    out.points.push_back(midspan);
  }
  out.distributed = scene.loads.distributed;
  return out;
}

std::vector<CombDrive> MakeCombDrives(const Scene& scene, const StructureDescription& structure) {
  std::vector<CombDrive> out;
  for (const SceneComb& c : scene.effects.combs) {
    CombDrive comb;
    comb.body = structure.FindBody(c.body);
    comb.fingers = c.fingers;
    comb.gap = c.gap;
    comb.overlap = c.overlap;
    comb.direction = c.direction;
    comb.thickness = structure.bodies.at(static_cast<std::size_t>(comb.body)).size.y();
    comb.voltage = c.voltage;
    comb.ac_voltage = c.ac_voltage;
    comb.frequency_hz = c.frequency.value_or(0.0);
    out.push_back(comb);
  }
  return out;
}

FramePullInOptions MakeFramePullInOptions(const Scene& scene) {
  FramePullInOptions out;
  const ElectrostaticEffect& e = *scene.effects.electrostatic;
  out.electrodes.gap = *scene.structure.gap;
  if (scene.effects.HasContact()) out.electrodes.separation = MakeContactOptions(scene).separation;
  if (!e.electrodes.empty()) {
    out.electrodes.electrodes.clear();
    for (const SceneElectrode& r : e.electrodes) out.electrodes.electrodes.push_back({r.x, r.z});
  }
  if (e.electrode_start || e.electrode_end) {  // a beam's electrode: a span of its length
    Electrode span;
    span.x = {e.electrode_start.value_or(0.0), e.electrode_end.value_or(scene.structure.length)};
    out.electrodes.electrodes = {span};
  }
  out.fringing = e.fringing;
  if (scene.analysis.voltage_max) out.fold.max_load = std::pow(*scene.analysis.voltage_max, 2);
  return out;
}

VoltageDrive MakeElectrodeDrive(const Scene& scene) {
  const ElectrostaticEffect& e = *scene.effects.electrostatic;
  return {e.voltage.value_or(0.0), e.ac_voltage, e.frequency.value_or(0.0)};
}

std::vector<FrameRecordPoint> MakeFrameRecord(const Scene& scene,
                                              const StructureDescription& structure) {
  if (scene.structure.kind == StructureKind::kCantilever) {
    return {{structure.FindNode("tip"), -1, -1, 0.0}};
  }
  if (scene.structure.kind == StructureKind::kBridge) return {{-1, -1, 0, 0.5}};  // midspan
  std::vector<FrameRecordPoint> named, out;
  for (const std::string& name : scene.analysis.record) {
    const int node = structure.FindNode(name);
    named.push_back({node, node >= 0 ? -1 : structure.FindBody(name)});
  }
  for (std::size_t b = 0; b < structure.bodies.size(); ++b) {
    named.push_back({-1, static_cast<int>(b)});
  }
  for (const FrameRecordPoint& point : named) {
    const bool listed = std::any_of(out.begin(), out.end(), [&](const FrameRecordPoint& p) {
      return p.node == point.node && p.body == point.body;
    });
    if (!listed) out.push_back(point);
  }
  return out;
}

}  // namespace cosmems
