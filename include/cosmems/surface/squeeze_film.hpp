#pragma once

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <utility>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/surface/gap_integral.hpp"

namespace cosmems {

/// The gas between beam and substrate.
struct SqueezeFilmOptions {
  double viscosity = 1.81e-5;  ///< Pa s (air at 20 C)
  /// m; > 0 adds the rarefied gas's slip (air at 1 atm: 68 nm), 0 leaves it out.
  double mean_free_path = 0.0;

  void Validate() const {
    RequirePositive("squeeze_film.viscosity", viscosity);
    RequireWithin("squeeze_film.mean_free_path", mean_free_path, 0.0, 1e-3);
  }
  /// These options, once Validate() accepts them.
  SqueezeFilmOptions Validated() const {
    Validate();
    return *this;
  }

  /// mu_eff(d) / d^3 and its derivative in d [SI]: the film's coefficient per b^3 on a strip
  /// (SqueezeFilm), per unit of a plate's shape factor (PlateSqueezeFactors).
  std::pair<double, double> Coefficient(double gap) const {
    const double mu = viscosity;
    const double g3 = gap * gap * gap;
    if (mean_free_path == 0.0) return {mu / g3, -3.0 * mu / (g3 * gap)};
    const double kn = mean_free_path / gap;
    const double slip = 1.0 + 9.638 * std::pow(kn, 1.159);
    const double mu_eff = mu / slip;
    // d(slip)/d(gap) = 9.638 * 1.159 Kn^0.159 dKn/dgap, dKn/dgap = -Kn / gap.
    const double dslip = -9.638 * 1.159 * std::pow(kn, 1.159) / gap;
    const double dmu_eff = -mu * dslip / (slip * slip);
    return {mu_eff / g3, dmu_eff / g3 - 3.0 * mu_eff / (g3 * gap)};
  }
};

/// A gas film's force: only a velocity-dependent part (EvaluateViscous), nothing at rest.
class GasFilmForce : public NonlinearForce {
 public:
  bool Evaluate(const Eigen::VectorXd& /*d*/, Eigen::VectorXd& /*force*/,
                ForceTangent& /*tangent*/) override {
    return true;  // at rest the film carries nothing
  }
  bool HasViscousPart() const override { return true; }
};

/// Squeeze-film damping: the gas pushed out from under a beam of width b moving toward the
/// substrate (and drawn back in as it moves away) resists with the line load
///   q = c(d) v_y,   c(d) = mu_eff(d) b^3 / d^3,
/// d(x) = gap + w(x) the local gap and v_y the axis's velocity toward +y. This is Reynolds'
/// equation for a long strip (b much less than the length) of incompressible gas with the
/// pressure released along both long edges: p = 6 mu v_y (y^2 - b^2/4) / d^3 across the width,
/// integrated. It holds while the squeeze number 12 mu w b^2 / (p_a d^2) stays well below 1
/// (0.1 for the reference cantilever's first mode at a 2 um gap in air); beyond it the gas
/// compresses and stores energy, which this leaves out. With a mean free path lambda,
/// mu_eff = mu / (1 + 9.638 Kn^1.159), Kn = lambda / d (Veijola et al. 1995), the slip of a
/// rarefied gas.
///
/// As a GasFilmForce it has only a velocity-dependent part, EvaluateViscous():
///   r = int N_w^T c(d) v_y dx,
///   dr/dd = int N_w^T c'(d) v_y N_w dx,   dr/dv = int N_w^T c(d) N_w dx,
/// on the adaptive quadrature of GapIntegral (c grows like 1/d^3 near contact). The power it
/// takes from the beam, v^T r = int c v_y^2 dx, is never negative. Allocates nothing.
template <int Dim>
class SqueezeFilm final : public GasFilmForce {
 public:
  /// `separation` [m]: where contact stops the faces (ContactOptions::separation); nearer than it
  /// the film keeps its coefficient there, as the gap pressures do (GapSpan::separation).
  SqueezeFilm(const BeamModel<Dim>& model, const SqueezeFilmOptions& options, double gap,
              double separation = 0.0)
      : options_(options.Validated()),
        integral_(model,
                  GapSpan{gap, 0.0, model.description().Length()}.WithSeparation(separation)),
        speed_m_s_(model.units().length / model.units().time) {}

  bool EvaluateViscous(const Eigen::VectorXd& d, const Eigen::VectorXd& v, double velocity_factor,
                       Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double length_m = integral_.length_m();
    return integral_.Integrate(d, [&](const typename GapIntegral<Dim>::Segment& s,
                                      const std::array<double, 4>& n, double gap, double weight) {
      double vy = 0.0;  // internal units
      for (int i = 0; i < 4; ++i) {
        if (s.dof[i] >= 0) vy += n[i] * v[s.dof[i]];
      }
      const double b3 = s.width_m * s.width_m * s.width_m;
      const auto [c, slope] = options_.Coefficient(gap);  // per b^3
      const double dc = integral_.Held(gap) ? 0.0 : slope;
      const double load = weight * b3 * c * vy * speed_m_s_;
      // d(load)/d(d_j) / N_j and d(load)/d(v_j) / N_j, the latter times dv/dd.
      const double stiffness = weight * b3 * dc * length_m * vy * speed_m_s_;
      const double damping = weight * b3 * c * speed_m_s_ * velocity_factor;
      for (int i = 0; i < 4; ++i) {
        if (s.dof[i] < 0) continue;
        force[s.dof[i]] += n[i] * load;
        for (int j = i; j < 4; ++j) {
          if (s.dof[j] >= 0) {
            tangent.band().Add(s.dof[i], s.dof[j], (stiffness + damping) * n[i] * n[j]);
          }
        }
      }
    });
  }

 private:
  SqueezeFilmOptions options_;
  GapIntegral<Dim> integral_;
  double speed_m_s_;  ///< m/s per internal velocity unit
};

}  // namespace cosmems
