#pragma once

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Which rod theory a Cosserat model follows.
enum class RodTheory {
  /// Simo-Reissner: extension and shear with their physical stiffnesses EA and kGA.
  kSimoReissner,
  /// The Kirchhoff limit (inextensible, unshearable), approached by multiplying EA and kGA by
  /// CosseratOptions::kirchhoff_factor. The axial and shear strains then shrink by that factor,
  /// and with them the model's distance from the constrained rod (the elastica in the plane).
  kKirchhoff,
};

/// Set-up options of a Cosserat rod model.
struct CosseratOptions {
  RodTheory theory = RodTheory::kSimoReissner;
  /// k in kGA: 5/6 for a solid rectangle (Timoshenko's energy-consistent value).
  double shear_factor = 5.0 / 6.0;
  /// The multiplier of EA and kGA in the Kirchhoff limit. The distance from the inextensible rod
  /// is then at most PL^2/EI (EI/(EA L^2) + EI/(kGA L^2)) / factor of L: 3.3e-6 L at
  /// PL^2/EI = 10 for the reference silicon cantilever (EA L^2/EI = 1.2e5) with 1e2, below the
  /// discretisation error of 50 elements (4e-5 L). Larger factors raise the Newton matrix's
  /// condition and the residual's round-off floor with them, and slow the solve down.
  double kirchhoff_factor = 1e2;

  /// The factor applied to EA and kGA.
  double ConstraintFactor() const {
    return theory == RodTheory::kKirchhoff ? kirchhoff_factor : 1.0;
  }

  /// Throws std::invalid_argument naming the field and value when an option is not usable.
  void Validate() const {
    RequirePositive("cosserat.shear_factor", shear_factor);
    RequireWithin("cosserat.kirchhoff_factor", kirchhoff_factor, 1.0, 1e8);
  }
};

}  // namespace cosmems
