#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

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
  /// The unit engagement direction.
  Eigen::Vector3d Axis() const { return direction.normalized(); }
  /// The unit direction across the fingers, in the plane: y x Axis().
  Eigen::Vector3d Lateral() const { return Eigen::Vector3d::UnitY().cross(Axis()); }
  /// N eps0 t / gap: the engagement force per volt squared [N/V^2].
  double ForcePerVoltSquared() const { return fingers * kVacuumPermittivity * thickness / gap; }
  /// The engagement force at `v` volts [N].
  double Force(double v) const { return ForcePerVoltSquared() * v * v; }
  /// The capacitance at engagement x [m] (no less than zero: fingers pulled apart) [F].
  double Capacitance(double x) const {
    return 2.0 * fingers * kVacuumPermittivity * thickness * std::max(overlap + x, 0.0) / gap;
  }
  /// The electrostatic negative stiffness across the fingers at `v` volts and engagement x
  /// [N/m]: C(x) V^2 / gap^2.
  double SideStiffness(double v, double x) const { return Capacitance(x) * v * v / (gap * gap); }
};

}  // namespace cosmems
