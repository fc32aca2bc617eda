#pragma once

#include <string>
#include <vector>

#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The design parameters of Tang, Nguyen and Howe's folded-flexure resonator (1989), in SI: a
/// shuttle on four folded beam pairs, each an inner beam from an anchor out to a truss and an
/// outer beam from the truss back to the shuttle, the trusses joining the pairs of each end.
/// The beams run along z, the shuttle moves along x.
struct FoldedFlexureDesign {
  double beam_length = 100e-6;             ///< m, each of the eight beams
  double beam_width = 2e-6;                ///< m, in the plane (the compliant direction's)
  double beam_spacing = 4e-6;              ///< m between an inner and an outer beam's axes
  double truss_width = 4e-6;               ///< m, the truss's extent along the beams
  double shuttle_width = 40e-6;            ///< m, along x
  double shuttle_length = 40e-6;           ///< m, along z
  double thickness = 2e-6;                 ///< m, of the beams, trusses and shuttle
  Material material{160e9, 2330.0, 0.22};  ///< polysilicon
  int elements = 10;                       ///< per beam
  int series_order = 1;

  /// The stiffness along x with rigid trusses and shuttle, 24 E I / L^3 (I = t w^3 / 12): each
  /// beam clamped-guided, two in series a pair, four pairs in parallel.
  double Stiffness() const {
    return 2.0 * material.young_modulus * thickness * beam_width * beam_width * beam_width /
           (beam_length * beam_length * beam_length);
  }
};

/// The folded flexure's netlist: nodes "anchor_SIDE", "joint_SIDE" (on the shuttle),
/// "truss_in_SIDE", "truss_out_SIDE" for SIDE "left_low", "right_low", "left_high", "right_high"
/// (x < 0 or > 0, z < 0 or > 0); bodies "truss_low", "truss_high" and "shuttle", centred at the
/// origin. Throws FieldError naming
/// the structure key of a parameter out of its range.
inline StructureDescription FoldedFlexure(const FoldedFlexureDesign& d) {
  RequirePositiveDesign({{"beam_length", d.beam_length},
                         {"beam_width", d.beam_width},
                         {"beam_spacing", d.beam_spacing},
                         {"truss_width", d.truss_width},
                         {"shuttle_length", d.shuttle_length},
                         {"thickness", d.thickness}});
  // The outer beams meet the shuttle a beam width inside its corners, the inner beams lie a
  // spacing further in: both pairs of a side must fit on the shuttle's half width.
  const double joint_x = 0.5 * d.shuttle_width - d.beam_width;
  const double anchor_x = joint_x - d.beam_spacing;
  if (!(anchor_x > 0.5 * d.beam_width)) {
    throw FieldError("structure.shuttle_width",
                     "too narrow for the beams: it must exceed 2 (2 beam_width + beam_spacing)");
  }
  StructureDescription s;
  s.series_order = d.series_order;
  const RectangularSection section{d.beam_width, d.thickness};
  const double edge = 0.5 * d.shuttle_length;
  const double truss = edge + d.beam_length;
  auto node = [&](const std::string& name, double x, double z, Support support) {
    s.nodes.push_back({name, {x, 0.0, z}, AnchorOf(support)});
    return static_cast<int>(s.nodes.size()) - 1;
  };
  std::vector<int> shuttle;
  for (int side_z : {-1, 1}) {
    std::vector<int> truss_nodes;
    for (int side_x : {-1, 1}) {
      const std::string side =
          std::string(side_x < 0 ? "left" : "right") + (side_z < 0 ? "_low" : "_high");
      const int anchor =
          node("anchor_" + side, side_x * anchor_x, side_z * edge, Support::kClamped);
      const int joint = node("joint_" + side, side_x * joint_x, side_z * edge, Support::kFree);
      const int in = node("truss_in_" + side, side_x * anchor_x, side_z * truss, Support::kFree);
      const int out = node("truss_out_" + side, side_x * joint_x, side_z * truss, Support::kFree);
      s.members.push_back({anchor, in, d.material, section, d.elements});
      s.members.push_back({out, joint, d.material, section, d.elements});
      shuttle.push_back(joint);
      truss_nodes.push_back(in);
      truss_nodes.push_back(out);
    }
    s.bodies.push_back({side_z < 0 ? "truss_low" : "truss_high",
                        {0.0, 0.0, side_z * (truss + 0.5 * d.truss_width)},
                        {d.shuttle_width, d.thickness, d.truss_width},
                        d.material.density,
                        truss_nodes});
  }
  s.bodies.push_back({"shuttle",
                      {0.0, 0.0, 0.0},
                      {d.shuttle_width, d.thickness, d.shuttle_length},
                      d.material.density,
                      shuttle});
  s.Validate();
  return s;
}

}  // namespace cosmems
