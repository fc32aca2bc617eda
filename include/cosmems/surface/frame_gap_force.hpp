#pragma once

#include <Eigen/Core>

#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_gap_points.hpp"
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
/// member or a body lies over an electrode (FrameGapPoints), each point at its own gap
/// g = g_0 + u_y:
///   r(d) = sum over points of n p(g) A,   dr/dd = sum of n p'(g) n^T A,
/// n the point's u_y per unit of each degree of freedom and A its share of the face's area.
/// Evaluate() allocates nothing and returns false where a gap closes (g <= 0) or is not finite.
template <class Pressure>
class FrameGapForce final : public FrameElementForce {
 public:
  /// Throws std::invalid_argument for the options FrameGapPoints refuses.
  FrameGapForce(const FrameModel& model, Pressure pressure, const FrameGapOptions& options)
      : points_(model, options), pressure_(pressure), force_n_(model.units().force) {}

  /// Scales the pressure by `scale` from now on (V^2 for the electrostatic pressure at 1 V: a
  /// transient's voltage in time); 1 at construction. Integrate() is not scaled.
  void SetScale(double scale) { scale_ = scale; }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double length_m = points_.length_m();
    for (const FrameGapPoints::Point& point : points_.points()) {
      const double gap = points_.Gap(point, d);
      if (!(gap > 0.0)) return false;
      const Pressure pressure = AtFaceWidth(pressure_, point.width_m);
      const double area = scale_ * point.area_m2;
      const double p = pressure.Value(gap) * area / force_n_;
      const double dp = points_.Held(gap) ? 0.0 : pressure.Slope(gap) * area * length_m / force_n_;
      for (int i = 0; i < point.count; ++i) {
        force[point.dof[i]] += point.n[i] * p;
        for (int j = i; j < point.count; ++j) {
          tangent.band().Add(point.dof[i], point.dof[j], dp * point.n[i] * point.n[j]);
        }
      }
    }
    return true;
  }

  FrameModel::ElementVector LocalForce(const Eigen::VectorXd& d, int e) const override {
    FrameModel::ElementVector out = FrameModel::ElementVector::Zero();
    for (int k = points_.first(e); k < points_.first(e + 1); ++k) {
      const FrameGapPoints::Point& point = points_.points()[k];
      const double p = AtFaceWidth(pressure_, point.width_m).Value(points_.Gap(point, d));
      out += point.local * (p * scale_ * point.area_m2 / force_n_);
    }
    return out;
  }

  /// The capacitance [F] of the faces over the electrodes at d, with Palmer's correction when
  /// the pressure has fringing (an electrostatic pressure's; independent of its voltage).
  double Capacitance(const Eigen::VectorXd& d) const {
    double sum = 0.0;
    for (const FrameGapPoints::Point& point : points_.points()) {
      sum += AtFaceWidth(pressure_, point.width_m).CapacitancePerArea(points_.Gap(point, d)) *
             point.area_m2;
    }
    return sum;
  }

 private:
  FrameGapPoints points_;
  Pressure pressure_;
  double force_n_;      ///< newtons per internal force unit
  double scale_ = 1.0;  ///< the pressure's factor (SetScale)
};

}  // namespace cosmems
