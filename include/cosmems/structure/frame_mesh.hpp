#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/structure/member_axes.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The elements and nodes a StructureDescription meshes into, and what carries each node's
/// motion: its own six degrees of freedom, or the rigid body it is attached to.
struct FrameMesh {
  /// A carrier of six degrees of freedom (u, theta about its reference point).
  struct Carrier {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m: the node, or the body's centre
    AnchorMask anchor{};
    int body = -1;  ///< the body it is, or -1 for a node
  };
  struct Node {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
    int carrier = 0;
    /// m from the carrier's reference point: nonzero only for a node on a body, which moves by
    /// u = u_c + theta_c x offset.
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  };
  struct Element {
    int member = 0;
    int from = 0;          ///< mesh node at xi = 0
    int to = 0;            ///< mesh node at xi = 1
    Eigen::Matrix3d axes;  ///< rows: the local x, y, z in global coordinates
    double length = 0.0;   ///< m
  };

  std::vector<Node> nodes;        ///< the description's nodes (same indices), then interior nodes
  std::vector<Element> elements;  ///< member by member, from its first node to its second
  std::vector<Carrier> carriers;
  std::vector<int> body_carrier;  ///< the carrier of each body

  explicit FrameMesh(const StructureDescription& s) {
    const std::vector<int> body_of = s.BodyOfNode();
    for (const StructureBody& body : s.bodies) {
      body_carrier.push_back(static_cast<int>(carriers.size()));
      carriers.push_back({body.center, AnchorMask{}, static_cast<int>(body_carrier.size()) - 1});
    }
    for (std::size_t n = 0; n < s.nodes.size(); ++n) {
      const StructureNode& node = s.nodes[n];
      if (body_of[n] >= 0) {
        const StructureBody& body = s.bodies[body_of[n]];
        nodes.push_back({node.position, body_carrier[body_of[n]], node.position - body.center});
      } else {
        nodes.push_back({node.position, AddCarrier(node.position, node.anchor), {0, 0, 0}});
      }
    }
    for (std::size_t m = 0; m < s.members.size(); ++m) {
      const StructureMember& member = s.members[m];
      const Eigen::Vector3d a = s.nodes[member.from].position;
      const Eigen::Vector3d b = s.nodes[member.to].position;
      const Eigen::Matrix3d axes = MemberAxes(a, b, member.thickness_direction);
      const double length = (b - a).norm() / member.elements;
      int previous = member.from;
      for (int k = 1; k <= member.elements; ++k) {
        int next = member.to;
        if (k < member.elements) {
          const Eigen::Vector3d p = a + (b - a) * (static_cast<double>(k) / member.elements);
          next = static_cast<int>(nodes.size());
          nodes.push_back({p, AddCarrier(p, AnchorMask{}), {0, 0, 0}});
        }
        elements.push_back({static_cast<int>(m), previous, next, axes, length});
        previous = next;
      }
    }
  }

 private:
  int AddCarrier(const Eigen::Vector3d& position, const AnchorMask& anchor) {
    carriers.push_back({position, anchor, -1});
    return static_cast<int>(carriers.size()) - 1;
  }
};

}  // namespace cosmems
