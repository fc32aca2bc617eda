#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/time/voltage_drive.hpp"

namespace cosmems {

/// A lateral comb drive between a rigid body and an anchor: `fingers` movable fingers on the
/// body, each between two fixed ones at `gap` on either side, engaged over `overlap` along
/// `direction` (in the substrate plane), with the fingers as thick as the body. Parallel-plate
/// fields between the fingers' sides, without fringing: the capacitance
/// C = 2 N eps0 t (overlap + x) / gap at an engagement x, the engagement force dC/dx V^2 / 2 =
/// N eps0 t V^2 / gap along `direction`, constant in x, and across it (in the plane) the
/// electrostatic negative stiffness of the fingers' two sides, 2 N eps0 t (overlap + x) V^2 /
/// gap^3, which a suspension too soft sideways cannot hold (the side instability). The force
/// acts at the body's centre.
struct CombDrive {
  int body = -1;         ///< the body of the structure that carries the movable fingers
  int fingers = 0;       ///< movable fingers
  double gap = 0.0;      ///< m, between a movable finger and each fixed neighbour
  double overlap = 0.0;  ///< m, the fingers' engagement at rest
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< engagement direction (normalised)
  double thickness = 0.0;  ///< m, the fingers' height: the body's thickness
  double voltage = 0.0;    ///< V: the constant part (all of it, in statics)
  /// V(t) = voltage + ac_voltage sin(2 pi frequency_hz t) in a transient
  double ac_voltage = 0.0;
  double frequency_hz = 0.0;

  /// Throws std::invalid_argument naming the first field out of range.
  void Validate() const {
    auto fail = [](const std::string& what) { throw std::invalid_argument("comb drive: " + what); };
    if (body < 0) fail("names no body");
    if (fingers < 1) fail("fingers must be at least 1");
    if (!(gap > 0.0) || !std::isfinite(gap)) fail("gap must be positive");
    if (!(overlap > 0.0) || !std::isfinite(overlap)) fail("overlap must be positive");
    if (!(thickness > 0.0) || !std::isfinite(thickness)) fail("thickness must be positive");
    if (!std::isfinite(voltage)) fail("voltage must be finite");
    if (!std::isfinite(ac_voltage)) fail("ac_voltage must be finite");
    if (!(frequency_hz >= 0.0) || !std::isfinite(frequency_hz)) {
      fail("frequency must be finite and not negative");
    }
    if (!direction.allFinite() || std::abs(direction.y()) > 1e-12 * direction.norm() ||
        !(direction.norm() > 0.0)) {
      fail("direction must be a non-zero vector in the substrate plane (y = 0)");
    }
  }
  /// The voltage in time.
  VoltageDrive Drive() const { return {voltage, ac_voltage, frequency_hz}; }
  /// The unit engagement direction, in the substrate plane (Validate() allows a y of round-off).
  Eigen::Vector3d Axis() const {
    return Eigen::Vector3d(direction.x(), 0.0, direction.z()).normalized();
  }
  /// The unit direction across the fingers, in the plane: y x Axis().
  Eigen::Vector3d Lateral() const { return Eigen::Vector3d::UnitY().cross(Axis()); }
  /// N eps0 t / gap: the engagement force per volt squared [N/V^2].
  double ForcePerVoltSquared() const { return fingers * kVacuumPermittivity * thickness / gap; }
  /// The engagement force at `v` volts [N] with the fingers y [m] off centre (|y| < gap):
  /// V^2 dC/dx / 2 = N eps0 t V^2 (1/(gap - y) + 1/(gap + y)) / 2.
  double Force(double v, double y = 0.0) const {
    return 0.5 * ForcePerVoltSquared() * gap * v * v * (1.0 / (gap - y) + 1.0 / (gap + y));
  }
  /// The capacitance [F] at engagement x [m] with the movable fingers moved y [m] across them
  /// (toward one fixed neighbour, away from the other): N eps0 t (overlap + x) (1/(gap - y) +
  /// 1/(gap + y)), no less than zero (fingers pulled apart). Needs |y| < gap.
  double Capacitance(double x, double y = 0.0) const {
    return fingers * kVacuumPermittivity * thickness * std::max(overlap + x, 0.0) *
           (1.0 / (gap - y) + 1.0 / (gap + y));
  }
  /// The electrostatic negative stiffness across the fingers at `v` volts and engagement x
  /// [N/m]: C(x) V^2 / gap^2.
  double SideStiffness(double v, double x) const { return Capacitance(x) * v * v / (gap * gap); }
};

/// Throws std::invalid_argument for a comb CombDrive::Validate() refuses or one whose body is
/// not among a structure's `bodies`.
inline void ValidateCombDrives(const std::vector<CombDrive>& combs, int bodies) {
  for (const CombDrive& comb : combs) {
    comb.Validate();
    if (comb.body >= bodies) throw std::invalid_argument("comb drive: names no body");
  }
}

}  // namespace cosmems
