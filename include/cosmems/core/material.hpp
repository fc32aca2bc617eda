#pragma once

#include <string>

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// An isotropic linear-elastic material.
struct Material {
  double young_modulus = 0.0;   ///< E [Pa]
  double density = 0.0;         ///< rho [kg/m^3]
  double poisson_ratio = 0.22;  ///< nu [-]; enters the shear modulus of torsion

  /// G = E / (2 (1 + nu)) [Pa].
  double ShearModulus() const { return young_modulus / (2.0 * (1.0 + poisson_ratio)); }

  /// Throws std::invalid_argument naming `where` and the field when a value is not physical.
  void Validate(const std::string& where) const {
    RequirePositive(where + ".young_modulus", young_modulus);
    RequirePositive(where + ".density", density);
    RequireInRange(where + ".poisson_ratio", poisson_ratio, -1.0, 0.5);
  }
};

}  // namespace cosmems
