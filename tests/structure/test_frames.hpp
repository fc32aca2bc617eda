#pragma once

// Frames for the structure tests, built through the library's description and handed to the
// independent oracle (frame_oracle.hpp) with the same geometry and sections.

#include <string>

#include "cosmems/cosmems.hpp"
#include "frame_oracle.hpp"

namespace cosmems::test {

/// Polysilicon, and the 2 um x 2 um member section of the device tests.
inline Material Poly() { return Material{160e9, 2330.0, 0.22}; }
inline RectangularSection SquareSection() { return RectangularSection{2e-6, 2e-6}; }

inline int AddNode(StructureDescription& s, const std::string& name, Eigen::Vector3d position,
                   Support support = Support::kFree) {
  s.nodes.push_back({name, position, AnchorOf(support)});
  return static_cast<int>(s.nodes.size()) - 1;
}

inline void AddBeam(StructureDescription& s, int from, int to, int elements,
                    RectangularSection section = SquareSection(),
                    Eigen::Vector3d thickness_direction = Eigen::Vector3d::UnitY()) {
  s.members.push_back({from, to, Poly(), section, elements, thickness_direction});
}

inline void AddBody(StructureDescription& s, const std::string& name, Eigen::Vector3d center,
                    Eigen::Vector3d size, std::vector<int> nodes) {
  s.bodies.push_back({name, center, size, Poly().density, std::move(nodes)});
}

/// The same frame for the oracle: sections, materials and bodies' inertia written out.
inline oracle::Frame ToOracle(const StructureDescription& s) {
  oracle::Frame frame;
  for (const StructureNode& node : s.nodes) {
    frame.nodes.push_back(node.position);
    frame.fixed.push_back(node.anchor);
  }
  for (const StructureMember& m : s.members) {
    oracle::Member member;
    member.a = m.from;
    member.b = m.to;
    member.young = m.material.young_modulus;
    member.shear = m.material.young_modulus / (2.0 * (1.0 + m.material.poisson_ratio));
    const double w = m.section.width, t = m.section.thickness;
    member.area = w * t;
    member.iz = w * t * t * t / 12.0;
    member.iy = t * w * w * w / 12.0;
    member.j = m.section.TorsionConstant();
    member.polar = member.iy + member.iz;
    member.density = m.material.density;
    member.up = m.thickness_direction;
    member.elements = m.elements;
    frame.members.push_back(member);
  }
  for (const StructureBody& b : s.bodies) {
    oracle::Body body;
    body.center = b.center;
    body.mass = b.density * b.size.prod();
    const Eigen::Vector3d q = b.size.cwiseProduct(b.size);
    body.inertia.diagonal() << q.y() + q.z(), q.x() + q.z(), q.x() + q.y();
    body.inertia *= body.mass / 12.0;
    body.nodes = b.nodes;
    frame.bodies.push_back(body);
  }
  return frame;
}

/// The folded-flexure resonator of polysilicon (the library's generator, FoldedFlexure) with
/// beams of `length` meshed into `elements` each.
inline StructureDescription FoldedFlexure(double length, int elements) {
  FoldedFlexureDesign design;
  design.beam_length = length;
  design.material = Poly();
  design.elements = elements;
  return cosmems::FoldedFlexure(design);
}

}  // namespace cosmems::test
