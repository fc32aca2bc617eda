#pragma once

#include <Eigen/Core>
#include <utility>

#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_gap_integral.hpp"
#include "cosmems/surface/gap_pressures.hpp"

namespace cosmems {

/// A pressure whose value depends on the width of the face it acts on (the electrostatic
/// fringing correction) takes that width here; the others ignore it.
template <class Pressure>
Pressure AtFaceWidth(Pressure pressure, double /*width_m*/) {
  return pressure;
}
inline ElectrostaticPressure AtFaceWidth(ElectrostaticPressure pressure, double width_m) {
  pressure.width = width_m;
  return pressure;
}

/// A gap pressure p(g) (gap_pressures.hpp) pulling a frame toward the substrate wherever a
/// member or a body lies over an electrode, each point at its own gap g = g_0 + u_y, integrated
/// to the gap (FrameGapIntegral):
///   r(d) = integral of n p(g) dA,   dr/dd = integral of n p'(g) n^T dA,
/// n the point's u_y per unit of each degree of freedom.
/// Evaluate() allocates nothing and returns false where a gap closes (g <= 0) or is not finite.
template <class Pressure>
class FrameGapForce final : public FrameElementForce {
 public:
  /// Throws std::invalid_argument for the options FrameGapIntegral refuses.
  FrameGapForce(const FrameModel& model, Pressure pressure, const FrameGapOptions& options)
      : integral_(model, options), pressure_(pressure), force_n_(model.units().force) {}

  /// Scales the pressure by `scale` from now on (V^2 for the electrostatic pressure at 1 V: a
  /// transient's voltage in time); 1 at construction. Capacitance() is not scaled.
  void SetScale(double scale) { scale_ = scale; }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double length_m = integral_.length_m();
    const bool band = tangent.band_wanted();  // the slope only for the tangent
    return integral_.Integrate(
        d, nullptr,
        [&](const FrameGapIntegral::Face& face, double gap, double area_m2, double /*vy*/) {
          const Pressure pressure = AtFaceWidth(pressure_, face.width_m);
          const double area = scale_ * area_m2 / force_n_;
          const double slope = !band || integral_.Held(gap) ? 0.0 : pressure.Slope(gap) * length_m;
          return std::pair{pressure.Value(gap) * area, slope * area};
        },
        force, tangent);
  }

  FrameModel::ElementVector LocalForce(const Eigen::VectorXd& d, int e) const override {
    return integral_.LocalForce(
        d, e, [&](const FrameGapIntegral::Face& face, double gap, double area_m2) {
          return AtFaceWidth(pressure_, face.width_m).Value(gap) * scale_ * area_m2 / force_n_;
        });
  }

  /// The capacitance [F] of the faces over the electrodes at d, with Palmer's correction when
  /// the pressure has fringing (an electrostatic pressure's; independent of its voltage). NaN
  /// where a gap closes.
  double Capacitance(const Eigen::VectorXd& d) const {
    return integral_.Sum(d, [&](const FrameGapIntegral::Face& face, double gap, double area_m2) {
      return AtFaceWidth(pressure_, face.width_m).CapacitancePerArea(gap) * area_m2;
    });
  }

 private:
  FrameGapIntegral integral_;
  Pressure pressure_;
  double force_n_;      ///< newtons per internal force unit
  double scale_ = 1.0;  ///< the pressure's factor (SetScale)
};

}  // namespace cosmems
