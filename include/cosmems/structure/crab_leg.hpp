#pragma once

#include <string>
#include <vector>

#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The design parameters of a crab-leg resonator (Fedder 1994), in SI: a shuttle on four crab
/// legs, one at each corner, each a shin from the shuttle's edge out along z to a knee and a thigh
/// from the knee out along x to an anchor. The shuttle moves along x, across the shins.
struct CrabLegDesign {
  double thigh_length = 40e-6;             ///< m, along x, from the knee to the anchor
  double thigh_width = 4e-6;               ///< m, in the plane
  double shin_length = 100e-6;             ///< m, along z, from the shuttle to the knee
  double shin_width = 2e-6;                ///< m, in the plane (the compliant direction's)
  double shuttle_width = 40e-6;            ///< m, along x
  double shuttle_length = 40e-6;           ///< m, along z
  double thickness = 2e-6;                 ///< m, of the legs and the shuttle
  Material material{160e9, 2330.0, 0.22};  ///< polysilicon
  int elements = 10;                       ///< per thigh and per shin
  int series_order = 1;

  /// The stiffness along x with a rigid shuttle, Fedder's crab-leg result (Fedder 1994, PhD
  /// thesis, UC Berkeley, ch. 3), k = E t w_s^3 (4 L_s + a L_t) / (L_s^3 (L_s + a L_t)) with
  /// a = I_s / I_t = (w_s / w_t)^3: each shin bends with its shuttle end guided (the four legs
  /// keep the shuttle from turning) and its knee held against turning by the thigh, clamped at
  /// the anchor and propped at the knee by the shin, 4 E I_t / L_t. Both members are taken
  /// inextensible. The shin's axial strain softens that prop (its E A_s / L_s against the
  /// thigh's 12 E I_t / L_t^3, 20 to 1 at the defaults), and the thigh's adds in series: the
  /// frame is 1.4e-3 softer at the defaults. A rigid thigh (a -> 0) leaves four clamped-guided
  /// shins, 4 x 12 E I_s / L_s^3.
  double Stiffness() const {
    const double a =
        (shin_width / thigh_width) * (shin_width / thigh_width) * (shin_width / thigh_width);
    const double cube = shin_length * shin_length * shin_length;
    return material.young_modulus * thickness * shin_width * shin_width * shin_width *
           (4.0 * shin_length + a * thigh_length) / (cube * (shin_length + a * thigh_length));
  }
};

/// The crab-leg resonator's netlist: nodes "anchor_SIDE", "knee_SIDE" and "joint_SIDE" (on the
/// shuttle) for SIDE "left_low", "right_low", "left_high", "right_high" (x < 0 or > 0, z < 0 or
/// > 0); the body "shuttle", centred at the origin. The shins meet the shuttle at its corners.
/// Throws FieldError naming the structure key of a parameter out of its range.
inline StructureDescription CrabLeg(const CrabLegDesign& d) {
  RequirePositiveDesign({{"thigh_length", d.thigh_length},
                         {"thigh_width", d.thigh_width},
                         {"shin_length", d.shin_length},
                         {"shin_width", d.shin_width},
                         {"shuttle_width", d.shuttle_width},
                         {"shuttle_length", d.shuttle_length},
                         {"thickness", d.thickness}});
  // The shins run flush with the shuttle's sides parallel to them: the left and right ones must
  // not overlap, and the thighs must clear the shuttle's edge.
  const double joint_x = 0.5 * (d.shuttle_width - d.shin_width);
  if (!(joint_x > 0.5 * d.shin_width)) {
    throw FieldError("structure.shuttle_width",
                     "too narrow for the legs: it must exceed 2 shin_width");
  }
  if (!(d.shin_length > 0.5 * d.thigh_width)) {
    throw FieldError("structure.shin_length",
                     "too short: the thighs would overlap the shuttle (it must exceed "
                     "thigh_width / 2)");
  }
  StructureDescription s;
  s.series_order = d.series_order;
  const double edge = 0.5 * d.shuttle_length;
  const double knee_z = edge + d.shin_length;
  auto node = [&](const std::string& name, double x, double z, Support support) {
    s.nodes.push_back({name, {x, 0.0, z}, AnchorOf(support)});
    return static_cast<int>(s.nodes.size()) - 1;
  };
  std::vector<int> shuttle;
  for (int side_z : {-1, 1}) {
    for (int side_x : {-1, 1}) {
      const std::string side =
          std::string(side_x < 0 ? "left" : "right") + (side_z < 0 ? "_low" : "_high");
      const int anchor = node("anchor_" + side, side_x * (joint_x + d.thigh_length),
                              side_z * knee_z, Support::kClamped);
      const int knee = node("knee_" + side, side_x * joint_x, side_z * knee_z, Support::kFree);
      const int joint = node("joint_" + side, side_x * joint_x, side_z * edge, Support::kFree);
      s.members.push_back(
          {anchor, knee, d.material, RectangularSection{d.thigh_width, d.thickness}, d.elements});
      s.members.push_back(
          {knee, joint, d.material, RectangularSection{d.shin_width, d.thickness}, d.elements});
      shuttle.push_back(joint);
    }
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
