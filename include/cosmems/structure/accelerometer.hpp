#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "cosmems/core/constants.hpp"
#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/structure_description.hpp"

namespace cosmems {

/// The design parameters of a guided proof-mass accelerometer, in SI: a proof mass on four
/// straight beams (not folded: the simplest suspension whose closed form is exact), one from
/// each corner out along z to an anchor. It senses acceleration along x, across the beams.
struct AccelerometerDesign {
  double beam_length = 150e-6;  ///< m, each beam, along z
  /// m, in the plane (the sensitive direction's): below the thickness, so that the sensing mode
  /// is the lowest, apart from the mode out of the plane (equal sides would make them one)
  double beam_width = 1.5e-6;
  double mass_width = 200e-6;              ///< m, the proof mass along x
  double mass_length = 200e-6;             ///< m, the proof mass along z
  double thickness = 2e-6;                 ///< m, of the beams and the proof mass
  Material material{160e9, 2330.0, 0.22};  ///< polysilicon
  int elements = 10;                       ///< per beam
  int series_order = 1;

  /// The stiffness along x with a rigid proof mass: four clamped-guided beams (the mass does not
  /// turn), k = 4 x 12 E I / L^3 with I = t w^3 / 12 the in-plane bending's. Exact for
  /// Euler-Bernoulli beams: a transverse end displacement stretches none of them.
  double Stiffness() const {
    return 4.0 * material.young_modulus * thickness * beam_width * beam_width * beam_width /
           (beam_length * beam_length * beam_length);
  }

  /// The proof mass, kg.
  double ProofMass() const { return material.density * mass_width * thickness * mass_length; }

  /// The sensing mode's frequency, Hz: f = sqrt(k / m) / 2 pi with m the proof mass alone. The
  /// beams add 13/35 of their mass (Rayleigh, the clamped-guided static shape), which lowers
  /// the frequency by about 13/70 of their mass over the proof mass's (0.4 % at the defaults).
  double NaturalFrequency() const { return std::sqrt(Stiffness() / ProofMass()) / (2.0 * kPi); }

  /// The proof mass's static displacement along x under an acceleration (m/s^2) along x: the
  /// inertial force m a at its centre over k.
  double Displacement(double acceleration) const {
    return ProofMass() * acceleration / Stiffness();
  }
};

/// The accelerometer's netlist: nodes "anchor_SIDE" and "joint_SIDE" (on the proof mass) for
/// SIDE "left_low", "right_low", "left_high", "right_high" (x < 0 or > 0, z < 0 or > 0); the
/// body "proof_mass", centred at the origin. The beams meet the proof mass at its corners.
/// Throws FieldError naming the structure key of a parameter out of its range.
inline StructureDescription Accelerometer(const AccelerometerDesign& d) {
  RequirePositiveDesign({{"beam_length", d.beam_length},
                         {"beam_width", d.beam_width},
                         {"mass_width", d.mass_width},
                         {"mass_length", d.mass_length},
                         {"thickness", d.thickness}});
  // The beams run flush with the proof mass's sides along z: the left and right ones must not
  // overlap.
  const double joint_x = 0.5 * (d.mass_width - d.beam_width);
  if (!(joint_x > 0.5 * d.beam_width)) {
    throw FieldError("structure.mass_width",
                     "too narrow for the beams: it must exceed 2 beam_width");
  }
  StructureDescription s;
  s.series_order = d.series_order;
  const RectangularSection section{d.beam_width, d.thickness};
  const double edge = 0.5 * d.mass_length;
  std::vector<int> mass;
  for (int side_z : {-1, 1}) {
    for (int side_x : {-1, 1}) {
      const std::string side =
          std::string(side_x < 0 ? "left" : "right") + (side_z < 0 ? "_low" : "_high");
      s.nodes.push_back({"anchor_" + side,
                         {side_x * joint_x, 0.0, side_z * (edge + d.beam_length)},
                         AnchorOf(Support::kClamped)});
      s.nodes.push_back(
          {"joint_" + side, {side_x * joint_x, 0.0, side_z * edge}, AnchorOf(Support::kFree)});
      const int joint = static_cast<int>(s.nodes.size()) - 1;
      s.members.push_back({joint - 1, joint, d.material, section, d.elements});
      mass.push_back(joint);
    }
  }
  s.bodies.push_back({"proof_mass",
                      {0.0, 0.0, 0.0},
                      {d.mass_width, d.thickness, d.mass_length},
                      d.material.density,
                      mass});
  s.Validate();
  return s;
}

}  // namespace cosmems
