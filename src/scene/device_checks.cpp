#include "device_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cosmems/structure/floating_part.hpp"
#include "cosmems/structure/frame_size.hpp"
#include "scene_limits.hpp"
#include "toml_format.hpp"

namespace cosmems::internal {
namespace {

// The key that sets the most elements of one member: a frame's beam that gives its own count,
// else model.elements (every member of a parametric device takes it).
std::string ElementsKey(const Scene& scene) {
  std::string key = "model.elements";
  int most = 0;
  const std::vector<SceneBeam>& beams = scene.structure.beams;
  for (std::size_t i = 0; i < beams.size(); ++i) {
    const int elements = beams[i].elements.value_or(scene.model.elements);
    if (elements <= most) continue;
    most = elements;
    key = beams[i].elements ? "structure.beams[" + std::to_string(i) + "].elements"
                            : "model.elements";
  }
  return key;
}

// "\"a\"", "\"a\" and \"b\"", "\"a\", \"b\", \"c\", \"d\" and 12 more": the first few names.
std::string SomeNames(const StructureDescription& s, const std::vector<int>& nodes) {
  constexpr std::size_t kNamed = 4;
  std::string out;
  const std::size_t named = std::min(nodes.size(), kNamed);
  for (std::size_t i = 0; i < named; ++i) {
    if (i > 0) out += i + 1 == named && named == nodes.size() ? " and " : ", ";
    out += "\"" + s.nodes[nodes[i]].name + "\"";
  }
  if (nodes.size() > named) out += " and " + std::to_string(nodes.size() - named) + " more";
  return out;
}

// A direction for a message: the vector scaled to its largest component, to 3 decimals.
std::string Direction(const Eigen::Vector3d& v) {
  const Eigen::Vector3d unit = v / v.cwiseAbs().maxCoeff();
  std::string out = "[";
  for (int k = 0; k < 3; ++k) {
    const double rounded = std::round(unit[k] * 1000.0) / 1000.0;
    out += (k > 0 ? ", " : "") + FormatNumber(rounded == 0.0 ? 0.0 : rounded);
  }
  return out + "]";
}

}  // namespace

void CheckDeviceSize(const TomlFieldReader& r, const Scene& scene,
                     const StructureDescription& structure) {
  const std::string key = ElementsKey(scene);
  // Counted first: FrameSizeOf allocates in proportion to it.
  const std::int64_t elements = FrameElementCount(structure);
  const std::string made = "the device's " + std::to_string(structure.members.size()) +
                           " members make " + std::to_string(elements) + " elements";
  r.Require(elements <= kMaxDeviceElements, key,
            made + ", more than the " + std::to_string(kMaxDeviceElements) +
                " a device's model may hold (doc/scenes.md, Limits)");
  const FrameSize size = FrameSizeOf(structure);
  const double bytes = DeviceBytes(size);
  r.Require(bytes <= kMaxDeviceBytes, key,
            made + " and " + std::to_string(size.unknowns) + " unknowns in a band of up to " +
                std::to_string(size.bandwidth) + ": about " +
                FormatNumber(std::round(bytes / 1e8) / 10.0) + " GB, more than the " +
                FormatNumber(kMaxDeviceBytes / 1e9) +
                " GB a device's model may take (doc/scenes.md, Limits)");
}

void CheckFrameSupports(const TomlFieldReader& r, const StructureDescription& structure) {
  const std::optional<FloatingPart> part = FindFloatingPart(structure);
  if (!part) return;
  const bool one = part->nodes.size() == 1;
  std::string what = (one ? "node " : "nodes ") + SomeNames(structure, part->nodes);
  std::string with;
  if (!part->members.empty()) {
    with = std::to_string(part->members.size()) + (part->members.size() == 1 ? " beam" : " beams");
  }
  for (int b : part->bodies) {
    with += (with.empty() ? "the body \"" : ", the body \"") + structure.bodies[b].name + "\"";
  }
  if (!with.empty()) what += " (with " + with + ")";
  what += one ? " floats: " : " float: ";
  if (part->anchors.empty()) {
    const std::string give =
        one ? "no support holds it (give it" : "no support holds them (give one of them";
    r.FailWithoutValue("structure.nodes", what + give + " a support, such as \"clamped\")");
  }
  const std::string motion = part->rotation.isZero(0.0)
                                 ? "a translation along " + Direction(part->translation)
                                 : "a rotation about " + Direction(part->rotation);
  const bool many = part->anchors.size() > 1;
  r.FailWithoutValue("structure.nodes", what + (many ? "the supports at " : "the support at ") +
                                            SomeNames(structure, part->anchors) +
                                            (many ? " leave " : " leaves ") +
                                            (one ? "it" : "them") + " a rigid motion, " + motion +
                                            " (fix more of the dofs, such as with \"clamped\")");
}

}  // namespace cosmems::internal
