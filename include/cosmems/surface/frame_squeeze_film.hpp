#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_gap_integral.hpp"
#include "cosmems/surface/plate_squeeze_factors.hpp"
#include "cosmems/surface/squeeze_film.hpp"

namespace cosmems {

/// Squeeze-film damping under a frame whose faces lie `gap` above the substrate at their lowest:
/// every member parallel to the substrate is a strip, c(d) = mu_eff(d) b^3 / d^3 per length at
/// each of its points' own gap d (SqueezeFilm's law, integrated to the gap by FrameGapIntegral
/// as on the beam: c grows like 1/d^3 near contact), and every body is a
/// rigid plate whose film is the rectangular plate's Reynolds solution (PlateSqueezeFactors):
///   F_y = -mu_eff(h) / h^3 translation v_y,  M_x, M_z alike with the tilt factors,
/// h the gap under the plate's centre (the tilt's variation of the gap across the plate is left
/// out of the coefficients, small while the tilt moves an edge by much less than h). Where a
/// member meets a body, each keeps its own film. As a GasFilmForce it has only a
/// velocity-dependent part; the power it takes, v^T r, is never negative. Allocates nothing.
class FrameSqueezeFilm final : public GasFilmForce {
 public:
  /// Throws std::invalid_argument for a gap that is not positive or invalid options.
  FrameSqueezeFilm(const FrameModel& model, const SqueezeFilmOptions& options, double gap)
      : options_(options.Validated()),
        strips_(model, Strips(gap)),
        length_m_(model.units().length),
        time_s_(model.units().time),
        force_n_(model.units().force) {
    const auto& bodies = model.description().bodies;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const int carrier = model.mesh().body_carrier[b];
      Plate plate;
      plate.gap_m = bodies[b].center.y() - 0.5 * bodies[b].size.y() - strips_.substrate_m();
      plate.factors = PlateSqueezeFactors::Of(bodies[b].size.x(), bodies[b].size.z());
      plate.uy = model.CarrierDof(carrier, 1);
      plate.theta_x = model.CarrierDof(carrier, 3);
      plate.theta_z = model.CarrierDof(carrier, 5);
      // An anchored body does not move.
      if (plate.uy >= 0 || plate.theta_x >= 0 || plate.theta_z >= 0) plates_.push_back(plate);
    }
  }

  bool EvaluateViscous(const Eigen::VectorXd& d, const Eigen::VectorXd& v, double velocity_factor,
                       Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double speed_m_s = length_m_ / time_s_;
    // r = n c v_y; dr/dd = n c' v_y n^T, dr/dv = n c n^T (times dv/dd along the step).
    const bool open = strips_.Integrate(
        d, &v,
        [&](const FrameGapIntegral::Face& face, double gap, double area_m2, double v_y) {
          const auto [c, slope] = options_.Coefficient(gap);  // per b^3
          // b^3 times the strip's length at the point: b^2 times its area.
          const double b2a = face.width_m * face.width_m * area_m2 / force_n_;
          const double vy = v_y * speed_m_s;
          return std::pair{b2a * c * vy,
                           b2a * (slope * length_m_ * vy + c * speed_m_s * velocity_factor)};
        },
        force, tangent);
    if (!open) return false;
    for (const Plate& plate : plates_) {
      const double h = plate.gap_m + (plate.uy >= 0 ? d[plate.uy] * length_m_ : 0.0);
      if (!(h > 0.0)) return false;
      const auto [c, slope] = options_.Coefficient(h);
      if (plate.uy >= 0) {
        // F_y = c T v_y [N]: dF/du_y = c' T v_y, dF/dv_y = c T.
        const double vy = v[plate.uy] * speed_m_s;
        const double f = c * plate.factors.translation / force_n_;
        const double df = slope * plate.factors.translation * length_m_ / force_n_;
        force[plate.uy] += f * vy;
        tangent.band().Add(plate.uy, plate.uy, df * vy + f * speed_m_s * velocity_factor);
      }
      // M = c R omega [N m], omega [rad/s] the rate over the time unit; the moment in units of
      // force times length. Its dependence on u_y through c (c' R omega) is left out of the
      // tangent, which is symmetric and cannot hold it alone; Newton still converges on the
      // residual, a little slower while a plate tilts fast.
      for (const auto& [dof, factor] : {std::pair{plate.theta_x, plate.factors.tilt_x},
                                        std::pair{plate.theta_z, plate.factors.tilt_z}}) {
        if (dof < 0) continue;
        const double m = c * factor / (time_s_ * force_n_ * length_m_);
        force[dof] += m * v[dof];
        tangent.band().Add(dof, dof, m * velocity_factor);
      }
    }
    return true;
  }

 private:
  // The members' strips over the substrate (the plates have their own law).
  static FrameGapOptions Strips(double gap) {
    FrameGapOptions options{gap};
    options.plates = false;
    return options;
  }

  // A body's plate: its gap at rest, its film's shape factors and its carrier's u_y, theta_x
  // and theta_z degrees of freedom (-1 where held).
  struct Plate {
    double gap_m = 0.0;
    PlateSqueezeFactors factors;
    int uy = -1, theta_x = -1, theta_z = -1;
  };

  SqueezeFilmOptions options_;
  FrameGapIntegral strips_;  ///< the members' strips
  std::vector<Plate> plates_;
  double length_m_;  ///< metres per internal length unit
  double time_s_;    ///< seconds per internal time unit
  double force_n_;   ///< newtons per internal force unit
};

}  // namespace cosmems
