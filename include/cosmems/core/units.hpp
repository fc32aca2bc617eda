#pragma once

#include <cmath>

namespace cosmems {

/// The internal unit system: base units of length [m], force [N] and time [s].
///
/// MEMS quantities in SI span 30 decades (EI ~ 1e-12 N m^2, lengths ~ 1e-5 m). Every model works
/// in units chosen from the structure itself, so that geometrically similar problems at 100 nm
/// and at 1 mm produce the same internal numbers and the same relative answers. SI stays at
/// every public interface; conversion happens once at set-up and once on output.
struct UnitSystem {
  double length = 1.0;  ///< m
  double force = 1.0;   ///< N
  double time = 1.0;    ///< s

  /// Units from a beam: length L, force EI/L^2, time L^2 sqrt(rho A / EI). In them the beam's
  /// bending stiffness, mass per length and length are all 1, so f1 of a cantilever is
  /// 1.8751^2 / 2pi internal units.
  static UnitSystem ForBeam(double beam_length, double bending_stiffness, double mass_per_length) {
    UnitSystem u;
    u.length = beam_length;
    u.force = bending_stiffness / (beam_length * beam_length);
    u.time = beam_length * beam_length * std::sqrt(mass_per_length / bending_stiffness);
    return u;
  }

  double Mass() const { return force * time * time / length; }
  double Stress() const { return force / (length * length); }
  double Density() const { return Mass() / (length * length * length); }
  double Moment() const { return force * length; }
  double ForcePerLength() const { return force / length; }
};

}  // namespace cosmems
