#pragma once

#include <Eigen/Core>
#include <array>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cosmems/beam/frame_layout.hpp"
#include "cosmems/beam/support.hpp"
#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Which of a node's six degrees of freedom (NodalDof order) an anchor fixes.
using AnchorMask = std::array<bool, 6>;

/// The anchor a named support makes (see Fixes).
inline AnchorMask AnchorOf(Support support) {
  AnchorMask mask{};
  for (int d = 0; d < 6; ++d) mask[d] = Fixes(support, static_cast<NodalDof>(d));
  return mask;
}

/// A point of a device, in SI: where members meet, loads act and anchors hold.
struct StructureNode {
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
  AnchorMask anchor{};                                 ///< all false: free
};

/// A straight prismatic beam member between two nodes, meshed into `elements` equal elements.
/// Its section's thickness lies along `thickness_direction` (the substrate normal y for a member
/// in the device's plane), its width across its axis in the plane.
struct StructureMember {
  int from = 0;
  int to = 0;
  Material material;
  RectangularSection section;
  int elements = 1;
  Eigen::Vector3d thickness_direction = Eigen::Vector3d::UnitY();
  /// N, a residual axial force in the straight member (tension > 0), e.g. from fabrication
  /// stress: it enters every analysis through the member's geometric stiffness.
  double axial_load = 0.0;
};

/// A rigid block (plate, shuttle, proof mass, mirror) with its edges along x, y and z; the nodes
/// attached to it follow it rigidly.
struct StructureBody {
  std::string name;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< m
  Eigen::Vector3d size = Eigen::Vector3d::Zero();    ///< m, extents along x, y, z
  double density = 0.0;                              ///< kg/m^3
  std::vector<int> nodes;

  double Mass() const { return density * size.prod(); }
};

/// A device as a netlist of nodes, beam members and rigid bodies, in SI. Entries are named in
/// errors as a scene names them: structure.nodes[i], structure.beams[i], structure.bodies[i].
struct StructureDescription {
  std::vector<StructureNode> nodes;
  std::vector<StructureMember> members;
  std::vector<StructureBody> bodies;
  int series_order = 1;  ///< power-series terms of every member: 0 = Hermite + consistent mass
  /// The motion in the x-y plane alone (u_x, u_y, r_z: along the members and toward the
  /// substrate), the other three directions held: a planar beam's model. Every node lies in
  /// the plane z = 0 and every member's thickness along y.
  bool planar = false;

  /// The index of the node called `name`, or -1.
  int FindNode(const std::string& name) const {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (nodes[i].name == name) return static_cast<int>(i);
    }
    return -1;
  }

  /// The index of the body named `name`, or -1.
  int FindBody(const std::string& name) const {
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].name == name) return static_cast<int>(i);
    }
    return -1;
  }

  /// The body each node is attached to, or -1 (valid descriptions attach a node at most once).
  std::vector<int> BodyOfNode() const {
    std::vector<int> body(nodes.size(), -1);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      for (int n : bodies[b].nodes) body.at(n) = static_cast<int>(b);
    }
    return body;
  }

  /// Throws FieldError naming the entry and the key (structure.beams[3].nodes) and the reason.
  void Validate() const {
    if (members.empty()) throw FieldError("structure.beams", "a frame needs a beam");
    if (series_order < 0) {
      throw FieldError("model.series_order", "must be >= 0");
    }
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      const std::string where = "structure.nodes[" + std::to_string(i) + "]";
      for (int k = 0; k < 3; ++k) RequireFinite(where + ".position", nodes[i].position[k]);
      for (std::size_t j = 0; j < i; ++j) {
        if (nodes[j].name == nodes[i].name) {
          throw FieldError(where + ".name",
                           "already the name of structure.nodes[" + std::to_string(j) + "]");
        }
      }
    }
    for (std::size_t m = 0; m < members.size(); ++m) ValidateMember(m);
    if (planar) ValidatePlanar();
    std::vector<int> owner(nodes.size(), -1);
    for (std::size_t b = 0; b < bodies.size(); ++b) ValidateBody(b, owner);
  }

 private:
  void ValidateMember(std::size_t m) const {
    const StructureMember& member = members[m];
    const std::string where = "structure.beams[" + std::to_string(m) + "]";
    const int count = static_cast<int>(nodes.size());
    if (member.from < 0 || member.from >= count || member.to < 0 || member.to >= count) {
      throw FieldError(where + ".nodes", "a node index outside 0 ... " + std::to_string(count - 1));
    }
    const StructureNode& a = nodes[member.from];
    const StructureNode& b = nodes[member.to];
    const Eigen::Vector3d axis = b.position - a.position;
    const double scale = std::max(a.position.norm(), b.position.norm());
    if (!(axis.norm() > 1e-12 * scale)) {
      throw FieldError(where + ".nodes", "zero length (\"" + a.name + "\" and \"" + b.name +
                                             "\" are at the same position)");
    }
    member.material.Validate(where + ".material");
    RequireFinite(where + ".axial_load", member.axial_load);
    member.section.Validate(where);
    if (member.elements < 1) {
      throw FieldError(where + ".elements", "must be at least 1");
    }
    const Eigen::Vector3d t = member.thickness_direction;
    for (int k = 0; k < 3; ++k) RequireFinite(where + ".thickness_direction", t[k]);
    if (t.isZero(0.0)) throw FieldError(where + ".thickness_direction", "must not be zero");
    // Within about half a degree of the axis the width direction t x axis is ill-defined.
    if (!(axis.normalized().cross(t).norm() > 1e-2 * t.norm())) {
      throw FieldError(where + ".thickness_direction",
                       "parallel to the member from \"" + a.name + "\" to \"" + b.name +
                           "\"; a member not parallel to the substrate names its thickness "
                           "direction");
    }
  }

  void ValidatePlanar() const {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      if (nodes[i].position.z() != 0.0) {
        throw FieldError("model.dimension",
                         "2 (planar) needs every node at z = 0; structure.nodes[" +
                             std::to_string(i) + "] is not");
      }
    }
    for (std::size_t m = 0; m < members.size(); ++m) {
      const Eigen::Vector3d& t = members[m].thickness_direction;
      if (t.x() != 0.0 || t.z() != 0.0) {
        throw FieldError("model.dimension",
                         "2 (planar) needs every member's thickness along y; "
                         "structure.beams[" +
                             std::to_string(m) + "]'s is not");
      }
    }
    if (!bodies.empty()) throw FieldError("model.dimension", "2 (planar) takes no bodies");
  }

  void ValidateBody(std::size_t b, std::vector<int>& owner) const {
    const StructureBody& body = bodies[b];
    const std::string where = "structure.bodies[" + std::to_string(b) + "]";
    for (int k = 0; k < 3; ++k) {
      RequireFinite(where + ".center", body.center[k]);
      RequirePositive(where + ".size", body.size[k]);
    }
    RequirePositive(where + ".density", body.density);
    if (body.nodes.empty()) {
      throw FieldError(where + ".nodes", "empty: a body is held by the nodes attached to it");
    }
    for (int n : body.nodes) {
      if (n < 0 || n >= static_cast<int>(nodes.size())) {
        throw FieldError(where + ".nodes", "a node index outside the structure");
      }
      if (owner[n] >= 0) {
        throw FieldError(where + ".nodes", "node \"" + nodes[n].name +
                                               "\" is already attached to structure.bodies[" +
                                               std::to_string(owner[n]) + "]");
      }
      owner[n] = static_cast<int>(b);
      for (bool fixed : nodes[n].anchor) {
        if (fixed) {
          throw FieldError(where + ".nodes", "node \"" + nodes[n].name +
                                                 "\" is anchored; anchor a body through a beam, "
                                                 "not at one of its own nodes");
        }
      }
    }
  }
};

/// Throws FieldError("structure.KEY", "must be positive") at the first of a parametric
/// device's design parameters (KEY, value) that is not positive: a generator's refusal names the
/// scene key that set it.
inline void RequirePositiveDesign(
    std::initializer_list<std::pair<const char*, double>> parameters) {
  for (const auto& [key, value] : parameters) {
    if (!(value > 0.0)) throw FieldError(std::string("structure.") + key, "must be positive");
  }
}

}  // namespace cosmems
