#pragma once

#include <stdexcept>
#include <string>

#include "cosmems/beam/support.hpp"
#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// A cantilever's or a bridge's design, in SI: a straight prismatic beam along x from the
/// origin, its thickness along y (toward the substrate), its width along z.
struct StraightBeamDesign {
  bool bridge = false;  ///< false: clamped at x = 0 only; true: at both ends
  double length = 200e-6;
  Material material{169e9, 2330.0, 0.22};
  RectangularSection section{20e-6, 2e-6};
  int elements = 20;
  int series_order = 1;
  double axial_load = 0.0;  ///< N, residual, tension > 0
  bool planar = false;      ///< u_x, u_y and r_z alone
};

/// The cantilever or the bridge as a one-member netlist: nodes "root" (x = 0, clamped) and
/// "tip" (x = length; clamped for a bridge), one member of `elements` equal elements between
/// them. Its FrameModel numbers the chain field by field, as a beam's: the same unknowns and
/// band. Throws FieldError naming the scene key of a parameter out of its range.
inline StructureDescription StraightBeam(const StraightBeamDesign& d) {
  RequirePositiveDesign({{"length", d.length}});
  if (d.elements < 1) throw FieldError("model.elements", "must be at least 1");
  RequireFinite("structure.axial_load", d.axial_load);
  StructureDescription s;
  s.series_order = d.series_order;
  s.planar = d.planar;
  s.nodes.push_back({"root", {0.0, 0.0, 0.0}, AnchorOf(Support::kClamped)});
  s.nodes.push_back(
      {"tip", {d.length, 0.0, 0.0}, AnchorOf(d.bridge ? Support::kClamped : Support::kFree)});
  StructureMember member;
  member.from = 0;
  member.to = 1;
  member.material = d.material;
  member.section = d.section;
  member.elements = d.elements;
  member.axial_load = d.axial_load;
  s.members.push_back(member);
  return s;
}

}  // namespace cosmems
