#pragma once

#include <Eigen/Core>
#include <array>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/surface/gap_integral.hpp"

namespace cosmems {

/// A gap pressure p(d) (see gap_pressures.hpp) pulling the beam toward the substrate, as a
/// NonlinearForce: with d(x) = gap + w(x) the local gap (w = u_y of the axis, negative toward
/// the substrate) and b the width,
///   r(d) = int N_w^T b p(gap + w) dx,   dr/dd = int N_w^T b p'(gap + w) N_w dx,
/// N_w the Hermite shape functions of u_y (the static ones: the power-series terms are
/// frequency corrections). p' < 0: the tangent softens the beam, which is what makes it pull in.
/// The quadrature adapts to the gap (GapIntegral); below the contact plane (GapSpan::separation)
/// the pressure keeps its value on it; without contact, a state whose gap closes anywhere is
/// outside the force's domain: Evaluate() returns false. Evaluate() allocates nothing.
template <int Dim, typename Pressure>
class GapForce final : public NonlinearForce {
 public:
  GapForce(const BeamModel<Dim>& model, Pressure pressure, const GapSpan& span)
      : pressure_(pressure), integral_(model, span) {}

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double length_m = integral_.length_m();
    const bool band = tangent.band_wanted();
    return integral_.Integrate(d, [&](const typename GapIntegral<Dim>::Segment& s,
                                      const std::array<double, 4>& n, double gap, double weight) {
      const double w = weight * s.width_m;
      const double p = w * pressure_.Value(gap);
      for (int i = 0; i < 4; ++i) {
        if (s.dof[i] >= 0) force[s.dof[i]] += n[i] * p;
      }
      if (!band) return;
      const double dp = integral_.Held(gap) ? 0.0 : w * pressure_.Slope(gap) * length_m;
      for (int i = 0; i < 4; ++i) {
        if (s.dof[i] < 0) continue;
        for (int j = i; j < 4; ++j) {
          if (s.dof[j] >= 0) tangent.band().Add(s.dof[i], s.dof[j], dp * n[i] * n[j]);
        }
      }
    });
  }

  const Pressure& pressure() const { return pressure_; }
  Pressure& pressure() { return pressure_; }

 private:
  Pressure pressure_;
  GapIntegral<Dim> integral_;
};

}  // namespace cosmems
