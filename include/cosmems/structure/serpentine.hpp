#pragma once

#include <string>
#include <vector>

#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The design parameters of a plate suspended by four serpentine (meander) springs, in SI. Each
/// spring leaves a corner of the plate along x, away from it, and meanders: a connector along x,
/// a span along z (outward first, then back, ...), a connector, ..., `turns` spans and
/// `turns` + 1 connectors, the last one ending at the anchor.
struct SerpentineDesign {
  double span_length = 50e-6;              ///< m, the long segments, along z
  double connector_length = 10e-6;         ///< m, the short segments, along x (the spans' pitch)
  double beam_width = 2e-6;                ///< m, every segment's, in the plane
  int turns = 4;                           ///< the spans of each spring
  double plate_width = 100e-6;             ///< m, along x
  double plate_length = 100e-6;            ///< m, along z
  double thickness = 2e-6;                 ///< m, of the springs and the plate
  Material material{160e9, 2330.0, 0.22};  ///< polysilicon
  int elements = 4;                        ///< per segment
  int series_order = 1;

  /// The stiffness normal to the substrate (along y) with a rigid plate. The plate translates
  /// without turning (the four springs are mirror images), so each spring's plate end is
  /// guided, and Castigliano's theorem, the method of Fedder's serpentine-spring results (Fedder
  /// 1994, PhD thesis, UC Berkeley, ch. 3), gives its compliance as the energy of out-of-plane
  /// bending (B = E w t^3 / 12) and Saint-Venant torsion (T = G J) about the spring's elastic
  /// centre. With s the span, c the connector, N spans, n = floor((N + 1) / 2) connectors at the
  /// spans' far ends:
  ///   1 / k_spring = [n c s^2 / T + N s^3 / (3 B)] - [n c s / T + N s^2 / (2 B)]^2
  ///                  / [(N + 1) c / T + N s / B]          (moments about the run, x)
  ///                + (N + 1)^3 c^3 / (12 B) + N (N^2 - 1) s c^2 / (12 T)   (about z)
  /// and k = 4 k_spring. A frame loaded normal to its plane carries the load by these two alone,
  /// so the result is exact for Euler-Bernoulli members; J is the library's (Roark's series).
  /// A straight spring (s -> 0) is one clamped-guided beam of length (N + 1) c.
  double Stiffness() const {
    const RectangularSection section{beam_width, thickness};
    const double b = material.young_modulus * section.SecondMomentZ();
    const double t = material.ShearModulus() * section.TorsionConstant();
    const double s = span_length, c = connector_length, n = static_cast<double>((turns + 1) / 2);
    const double spans = turns;
    const double weight = (spans + 1.0) * c / t + spans * s / b;
    const double first = n * c * s / t + spans * s * s / (2.0 * b);
    const double second = n * c * s * s / t + spans * s * s * s / (3.0 * b);
    const double run = spans + 1.0;
    const double about_span = run * run * run * c * c * c / (12.0 * b) +
                              spans * (spans * spans - 1.0) * s * c * c / (12.0 * t);
    return 4.0 / (second - first * first / weight + about_span);
  }
};

/// The serpentine-suspended plate's netlist: for each spring SIDE ("left_low", "right_low",
/// "left_high", "right_high": x < 0 or > 0, z < 0 or > 0), nodes "joint_SIDE" (on the plate),
/// "bend_SIDE_1" ... "bend_SIDE_2N" (the meander's corners, two per span) and "anchor_SIDE";
/// the body "plate", centred at the origin. Throws FieldError naming the structure key of a
/// parameter out of its range.
inline StructureDescription Serpentine(const SerpentineDesign& d) {
  RequirePositiveDesign({{"span_length", d.span_length},
                         {"connector_length", d.connector_length},
                         {"beam_width", d.beam_width},
                         {"plate_width", d.plate_width},
                         {"plate_length", d.plate_length},
                         {"thickness", d.thickness}});
  if (d.turns < 1) throw FieldError("structure.turns", "must be at least 1");
  // Neighbouring spans lie a connector apart; the springs start flush with the plate's corners.
  if (!(d.connector_length > d.beam_width)) {
    throw FieldError("structure.connector_length",
                     "must exceed beam_width (neighbouring spans would touch)");
  }
  if (!(d.plate_length > 2.0 * d.beam_width)) {
    throw FieldError("structure.plate_length",
                     "too narrow for the springs: it must exceed 2 beam_width");
  }
  StructureDescription s;
  s.series_order = d.series_order;
  const RectangularSection section{d.beam_width, d.thickness};
  auto node = [&](const std::string& name, double x, double z, Support support) {
    s.nodes.push_back({name, {x, 0.0, z}, AnchorOf(support)});
    return static_cast<int>(s.nodes.size()) - 1;
  };
  auto member = [&](int from, int to) {
    s.members.push_back({from, to, d.material, section, d.elements});
  };
  const double start_x = 0.5 * d.plate_width;
  const double start_z = 0.5 * (d.plate_length - d.beam_width);
  std::vector<int> plate;
  for (int side_z : {-1, 1}) {
    for (int side_x : {-1, 1}) {
      const std::string side =
          std::string(side_x < 0 ? "left" : "right") + (side_z < 0 ? "_low" : "_high");
      int last = node("joint_" + side, side_x * start_x, side_z * start_z, Support::kFree);
      plate.push_back(last);
      double offset = 0.0;  // the meander's distance out from the plate's corner, along z
      for (int span = 1; span <= d.turns; ++span) {
        const double x = side_x * (start_x + span * d.connector_length);
        const int from = node("bend_" + side + "_" + std::to_string(2 * span - 1), x,
                              side_z * (start_z + offset), Support::kFree);
        member(last, from);
        offset = d.span_length - offset;
        last = node("bend_" + side + "_" + std::to_string(2 * span), x, side_z * (start_z + offset),
                    Support::kFree);
        member(from, last);
      }
      const int anchor =
          node("anchor_" + side, side_x * (start_x + (d.turns + 1) * d.connector_length),
               side_z * (start_z + offset), Support::kClamped);
      member(last, anchor);
    }
  }
  s.bodies.push_back({"plate",
                      {0.0, 0.0, 0.0},
                      {d.plate_width, d.thickness, d.plate_length},
                      d.material.density,
                      plate});
  s.Validate();
  return s;
}

}  // namespace cosmems
