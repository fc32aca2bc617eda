#pragma once

#include "cosmems/core/validation.hpp"
#include "cosmems/time/newton_options.hpp"

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

/// Newton's defaults for rods: NewtonOptions with a residual tolerance of 1e-9 instead of 1e-10.
/// A strain formed from nodal positions carries a round-off floor in the residual, of order
/// EA eps |u| / h: measured 1e-11 to 3e-11 of the reference size for the reference cantilever
/// (50 and 200 elements, PL^2/EI from 0.01 to 2), and the Kirchhoff factor higher in that limit.
/// 1e-10 would sit within a factor 3 of it and cost a haptic re-solve a third iteration (the
/// increment test ends the iterations at the floor either way). A residual of 1e-9 of the loads
/// is a deflection error of order 1e-9 L.
inline NewtonOptions RodNewtonOptions() {
  NewtonOptions options;
  options.residual_tolerance = 1e-9;
  return options;
}

/// Throws std::invalid_argument naming the field and value when a NewtonOptions is not usable.
inline void ValidateNewtonOptions(const NewtonOptions& options) {
  RequirePositive("newton.residual_tolerance", options.residual_tolerance);
  RequirePositive("newton.increment_tolerance", options.increment_tolerance);
  RequireWithin("newton.max_iterations", options.max_iterations, 1, 1000);
  RequireWithin("newton.max_cuts", options.max_cuts, 0, 50);
}

}  // namespace cosmems
