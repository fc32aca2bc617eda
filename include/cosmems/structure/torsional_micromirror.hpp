#pragma once

#include <cmath>
#include <string>

#include "cosmems/core/constants.hpp"
#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The design parameters of a torsional micromirror, in SI: a plate on two torsion beams along
/// x, one from the middle of each of its sides across x out to an anchor; it turns about x.
struct TorsionalMicromirrorDesign {
  double beam_length = 100e-6;   ///< m, each torsion beam, along x
  double beam_width = 3e-6;      ///< m, in the plane (unequal to the thickness: the two bending
                                 ///< planes of the beams ring apart)
  double plate_width = 100e-6;   ///< m, along x
  double plate_length = 100e-6;  ///< m, along z
  double thickness = 2e-6;       ///< m, of the beams and the plate
  Material material{160e9, 2330.0, 0.22};  ///< polysilicon
  int elements = 8;                        ///< per beam
  int series_order = 1;

  /// The stiffness against turning about x, N m / rad: the two beams in parallel, 2 G J / L, J
  /// Saint-Venant's torsion constant of the rectangle by Roark's series (the library's own,
  /// RectangularSection::TorsionConstant, within 0.5 % of the exact series), which the frame's
  /// members twist by: exact for a rigid plate.
  double Stiffness() const {
    return 2.0 * material.ShearModulus() *
           RectangularSection{beam_width, thickness}.TorsionConstant() / beam_length;
  }

  /// The plate's moment of inertia about x, m (l^2 + t^2) / 12, kg m^2.
  double PlateInertia() const {
    const double mass = material.density * plate_width * thickness * plate_length;
    return mass * (plate_length * plate_length + thickness * thickness) / 12.0;
  }

  /// The torsion mode's frequency, Hz, by Rayleigh's quotient with the beams' twist linear along
  /// them: f = sqrt(2 G J / L / (I_plate + 2 rho I_p L / 3)) / 2 pi, the beams' rotary inertia
  /// (I_p = I_y + I_z, the section's polar moment) joining at a third. The beams' inertia is a
  /// small part of the plate's, and the quotient's error is of its square (below 1e-9 here).
  double NaturalFrequency() const {
    const RectangularSection section{beam_width, thickness};
    const double beams = 2.0 * material.density * section.PolarMoment() * beam_length / 3.0;
    return std::sqrt(Stiffness() / (PlateInertia() + beams)) / (2.0 * kPi);
  }
};

/// The torsional micromirror's netlist, as the embedded `micromirror` scene writes it: nodes
/// "left_anchor", "left_hinge", "right_hinge", "right_anchor" along x; the body "mirror",
/// centred at the origin, on the hinges. Throws FieldError naming the structure key of a
/// parameter out of its range.
inline StructureDescription TorsionalMicromirror(const TorsionalMicromirrorDesign& d) {
  RequirePositiveDesign({{"beam_length", d.beam_length},
                         {"beam_width", d.beam_width},
                         {"plate_width", d.plate_width},
                         {"plate_length", d.plate_length},
                         {"thickness", d.thickness}});
  if (!(d.beam_width < d.plate_length)) {
    throw FieldError("structure.beam_width",
                     "wider than the plate's sides it meets: it must be below plate_length");
  }
  StructureDescription s;
  s.series_order = d.series_order;
  const double hinge = 0.5 * d.plate_width;
  const double anchor = hinge + d.beam_length;
  const RectangularSection section{d.beam_width, d.thickness};
  s.nodes.push_back({"left_anchor", {-anchor, 0.0, 0.0}, AnchorOf(Support::kClamped)});
  s.nodes.push_back({"left_hinge", {-hinge, 0.0, 0.0}, AnchorOf(Support::kFree)});
  s.nodes.push_back({"right_hinge", {hinge, 0.0, 0.0}, AnchorOf(Support::kFree)});
  s.nodes.push_back({"right_anchor", {anchor, 0.0, 0.0}, AnchorOf(Support::kClamped)});
  s.members.push_back({0, 1, d.material, section, d.elements});
  s.members.push_back({3, 2, d.material, section, d.elements});
  s.bodies.push_back({"mirror",
                      {0.0, 0.0, 0.0},
                      {d.plate_width, d.thickness, d.plate_length},
                      d.material.density,
                      {1, 2}});
  s.Validate();
  return s;
}

}  // namespace cosmems
