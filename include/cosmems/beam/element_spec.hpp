#pragma once

#include <string>

#include "cosmems/core/material.hpp"
#include "cosmems/core/rectangular_section.hpp"
#include "cosmems/core/units.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// One beam element as the user describes it, in SI. Every element carries its own material
/// and section, so tapered and multi-material beams are element lists like any other.
struct ElementSpec {
  double length = 0.0;  ///< m
  Material material;
  RectangularSection section;

  void Validate(const std::string& where) const {
    RequirePositive(where + ".length", length);
    material.Validate(where + ".material");
    section.Validate(where + ".section");
  }
};

/// An element's properties converted once into a model's internal units.
struct ElementProperties {
  double length = 0.0;
  double young_modulus = 0.0;
  double shear_modulus = 0.0;
  double density = 0.0;
  double area = 0.0;
  double second_moment_y = 0.0;  ///< I_y: bending in x-z
  double second_moment_z = 0.0;  ///< I_z: bending in x-y, toward the substrate
  double torsion_constant = 0.0;
  double polar_moment = 0.0;
  double half_thickness = 0.0;  ///< outer fibre distance in y
  double half_width = 0.0;      ///< outer fibre distance in z

  static ElementProperties From(const ElementSpec& spec, const UnitSystem& units) {
    const double l = units.length;
    const double l2 = l * l;
    const double l4 = l2 * l2;
    ElementProperties p;
    p.length = spec.length / l;
    p.young_modulus = spec.material.young_modulus / units.Stress();
    p.shear_modulus = spec.material.ShearModulus() / units.Stress();
    p.density = spec.material.density / units.Density();
    p.area = spec.section.Area() / l2;
    p.second_moment_y = spec.section.SecondMomentY() / l4;
    p.second_moment_z = spec.section.SecondMomentZ() / l4;
    p.torsion_constant = spec.section.TorsionConstant() / l4;
    p.polar_moment = spec.section.PolarMoment() / l4;
    p.half_thickness = 0.5 * spec.section.thickness / l;
    p.half_width = 0.5 * spec.section.width / l;
    return p;
  }
};

}  // namespace cosmems
