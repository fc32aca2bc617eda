#include "cosmems/scene/netlist_scene.hpp"

#include <sstream>
#include <stdexcept>

#include "cosmems/scene/frame_conversion.hpp"
#include "toml_format.hpp"

namespace cosmems {
namespace {

using internal::FormatFloat;

std::string Vector(const Eigen::Vector3d& v) {
  // + 0.0: a coordinate of -0 prints as 0.
  return "[" + FormatFloat(v.x() + 0.0) + ", " + FormatFloat(v.y() + 0.0) + ", " +
         FormatFloat(v.z() + 0.0) + "]";
}

std::string Quoted(const std::string& text) { return "\"" + text + "\""; }

// A named support when the anchor is one, else the list of its fixed dofs.
std::string SupportText(const AnchorMask& anchor) {
  constexpr const char* kNames[] = {"free", "clamped", "pinned", "guided"};
  constexpr Support kSupports[] = {Support::kFree, Support::kClamped, Support::kPinned,
                                   Support::kGuided};
  for (int i = 0; i < 4; ++i) {
    if (AnchorOf(kSupports[i]) == anchor) return Quoted(kNames[i]);
  }
  constexpr const char* kDofs[] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  std::string list;
  for (int d = 0; d < 6; ++d) {
    if (anchor[d]) list += (list.empty() ? "" : ", ") + Quoted(kDofs[d]);
  }
  return "[" + list + "]";
}

// What a frame scene cannot say yet of a beam's netlist: a reason naming the key, or "".
std::string Unprintable(const Scene& scene) {
  if (scene.model.dimension == 2) return "model.dimension = 2: a frame scene is 3-D";
  if (scene.structure.axial_load != 0.0) {
    std::ostringstream reason;
    reason << "structure.axial_load = " << scene.structure.axial_load
           << ": a frame scene's beams take no residual axial load";
    return reason.str();
  }
  if (!scene.loads.midspan_force.isZero(0.0)) {
    return "loads.midspan_force: the netlist has no node at midspan";
  }
  return "";
}

}  // namespace

std::string NetlistScene(const Scene& scene) {
  if (const std::string reason = Unprintable(scene); !reason.empty()) {
    throw std::invalid_argument(scene.source + ": " + reason);
  }
  const StructureDescription s = MakeStructureDescription(scene);
  std::ostringstream out;
  out << "# " << scene.source << " (structure.kind = \"" << ToString(scene.structure.kind)
      << "\") as a frame netlist to edit\n\n";
  out << "[structure]\nkind = \"frame\"\nthickness = " << FormatFloat(scene.structure.thickness)
      << "\n";
  if (scene.structure.gap) out << "gap = " << FormatFloat(*scene.structure.gap) << "\n";
  for (const StructureNode& node : s.nodes) {
    out << "\n[[structure.nodes]]\nname = " << Quoted(node.name)
        << "\nposition = " << Vector(node.position) << "\n";
    if (node.anchor != AnchorMask{}) out << "support = " << SupportText(node.anchor) << "\n";
  }
  for (const StructureMember& m : s.members) {
    out << "\n[[structure.beams]]\nnodes = [" << Quoted(s.nodes[m.from].name) << ", "
        << Quoted(s.nodes[m.to].name) << "]\nwidth = " << FormatFloat(m.section.width)
        << "\nthickness = " << FormatFloat(m.section.thickness) << "\nelements = " << m.elements
        << "\n";
    if (m.thickness_direction != Eigen::Vector3d::UnitY()) {
      out << "thickness_direction = " << Vector(m.thickness_direction) << "\n";
    }
  }
  for (const StructureBody& b : s.bodies) {
    out << "\n[[structure.bodies]]\nname = " << Quoted(b.name) << "\ncenter = " << Vector(b.center)
        << "\nsize = " << Vector(b.size) << "\nnodes = [";
    for (std::size_t i = 0; i < b.nodes.size(); ++i) {
      out << (i > 0 ? ", " : "") << Quoted(s.nodes[b.nodes[i]].name);
    }
    out << "]\n";
  }
  const SceneMaterial& material = scene.material;
  out << "\n[material]\nyoung_modulus = " << FormatFloat(material.young_modulus)
      << "\ndensity = " << FormatFloat(material.density)
      << "\npoisson_ratio = " << FormatFloat(material.poisson_ratio)
      << "\nplate_modulus = " << (material.plate_modulus ? "true" : "false") << "\n";
  out << "\n[model]\nelements = " << scene.model.elements
      << "\nseries_order = " << scene.model.series_order << "\n";
  out << "\n[loads]\ndistributed = " << Vector(scene.loads.distributed) << "\n";
  // A cantilever's tip load acts at its netlist's node "tip".
  if (!scene.loads.tip_force.isZero(0.0) || !scene.loads.tip_moment.isZero(0.0)) {
    out << "\n[[loads.points]]\nnode = \"tip\"\nforce = " << Vector(scene.loads.tip_force)
        << "\nmoment = " << Vector(scene.loads.tip_moment) << "\n";
  }
  for (const ScenePointLoad& p : scene.loads.points) {
    out << "\n[[loads.points]]\n"
        << (p.node ? "node = " + Quoted(*p.node) : "body = " + Quoted(*p.body))
        << "\nforce = " << Vector(p.force) << "\nmoment = " << Vector(p.moment) << "\n";
  }
  out << "\n[analysis]\ntype = \"" << ToString(scene.analysis.type) << "\"\n";
  if (scene.analysis.type == AnalysisType::kModal)
    out << "count = " << scene.analysis.count << "\n";
  return out.str();
}

}  // namespace cosmems
