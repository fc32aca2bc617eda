#pragma once

#include <algorithm>
#include <string>

#include "cosmems/core/validation.hpp"

namespace cosmems {

/// A solid rectangular cross-section: `thickness` along y (toward the substrate), `width`
/// along z. Bending toward the substrate (in the x-y plane) uses I_z = b t^3 / 12.
struct RectangularSection {
  double width = 0.0;      ///< b [m], along z
  double thickness = 0.0;  ///< t [m], along y

  double Area() const { return width * thickness; }
  /// I_z = b t^3 / 12 [m^4]: bending in the x-y plane (toward the substrate).
  double SecondMomentZ() const { return width * thickness * thickness * thickness / 12.0; }
  /// I_y = t b^3 / 12 [m^4]: bending in the x-z plane (across the width).
  double SecondMomentY() const { return thickness * width * width * width / 12.0; }
  /// Polar moment I_y + I_z [m^4]: the rotary inertia of torsion per unit density and length.
  double PolarMoment() const { return SecondMomentY() + SecondMomentZ(); }
  /// Saint-Venant torsion constant J [m^4] by Roark's series for a solid rectangle,
  /// J = a c^3 (1/3 - 0.21 (c/a) (1 - c^4 / (12 a^4))) with a >= c; within 0.5 % of the exact
  /// series for every aspect ratio.
  double TorsionConstant() const {
    const double a = std::max(width, thickness);
    const double c = std::min(width, thickness);
    const double r = c / a;
    return a * c * c * c * (1.0 / 3.0 - 0.21 * r * (1.0 - r * r * r * r / 12.0));
  }

  void Validate(const std::string& where) const {
    RequirePositive(where + ".width", width);
    RequirePositive(where + ".thickness", thickness);
  }
};

}  // namespace cosmems
