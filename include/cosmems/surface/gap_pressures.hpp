#pragma once

#include <cmath>

#include "cosmems/core/constants.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Physical constants of the surface forces (CODATA 2018), SI.
inline constexpr double kVacuumPermittivity = 8.8541878128e-12;  ///< F/m
inline constexpr double kReducedPlanck = 1.054571817e-34;        ///< J s
inline constexpr double kSpeedOfLight = 299792458.0;             ///< m/s

/// The pressures that pull a beam's lower face toward the substrate, each a function of the local
/// gap d [m] with its derivative: Value(d) [Pa] and Slope(d) = dValue/dd [Pa/m]. Each is the
/// force per unit area between two parallel plates at distance d, applied locally along the beam
/// (the proximity-force approximation, good while the gap varies slowly along the beam compared
/// with the gap itself).

/// Parallel-plate electrostatic pressure eps0 V^2 / (2 d^2). With `fringing`, the first-order
/// correction for the field lines leaving a beam of width b through its edges multiplies it by
/// (1 + 0.65 d / b) (Palmer's capacitance per area; Osterberg & Senturia use it for their pull-in
/// formulas).
struct ElectrostaticPressure {
  double voltage = 0.0;  ///< V
  double width = 0.0;    ///< m, the beam's (for fringing)
  bool fringing = false;

  double Value(double d) const {
    const double p = 0.5 * kVacuumPermittivity * voltage * voltage / (d * d);
    return fringing ? p * (1.0 + 0.65 * d / width) : p;
  }
  double Slope(double d) const {
    const double c = 0.5 * kVacuumPermittivity * voltage * voltage;
    return fringing ? -2.0 * c / (d * d * d) - 0.65 * c / (width * d * d) : -2.0 * c / (d * d * d);
  }
  /// The capacitance per unit area [F/m^2] at gap d, with Palmer's correction when `fringing`
  /// (independent of the voltage).
  double CapacitancePerArea(double d) const {
    return kVacuumPermittivity / d * (fringing ? 1.0 + 0.65 * d / width : 1.0);
  }
};

/// The Casimir pressure between ideal conductors, pi^2 hbar c / (240 d^4).
struct CasimirPressure {
  static constexpr double Coefficient() {
    return kPi * kPi * kReducedPlanck * kSpeedOfLight / 240.0;
  }
  double Value(double d) const { return Coefficient() / (d * d * d * d); }
  double Slope(double d) const { return -4.0 * Coefficient() / (d * d * d * d * d); }
};

/// The non-retarded van der Waals pressure A_H / (6 pi d^3), A_H the Hamaker constant.
struct VanDerWaalsPressure {
  double hamaker = 0.0;  ///< J

  double Value(double d) const { return hamaker / (6.0 * kPi * d * d * d); }
  double Slope(double d) const { return -hamaker / (2.0 * kPi * d * d * d * d); }
};

}  // namespace cosmems
