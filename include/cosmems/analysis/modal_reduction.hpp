#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/core/constants.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/modal_model.hpp"

namespace cosmems {

/// Builds the modal model from `modes` of `model` (a BeamModel or a FrameModel). For series order
/// >= 1 the modes solve the polynomial problem P(l) x = 0, whose modal mass is x^T P'(l) x with
/// -P'(l) = M_0 + 2 l M_2 + 3 l^2 M_4 + ...; shapes are scaled to unit modal mass in that
/// sense (for order 0 it is the usual x^T M_0 x = 1).
template <class Model>
ModalModel MakeModalModel(const Model& model, const ModalResult& modes,
                          const DampingModel& damping) {
  ModalModel out;
  const int n = model.FreeDofCount();
  out.shapes.resize(n, static_cast<Eigen::Index>(modes.modes.size()));
  Eigen::VectorXd product(n), weighted(n);
  for (std::size_t i = 0; i < modes.modes.size(); ++i) {
    const Mode& mode = modes.modes[i];
    const double omega_si = 2.0 * kPi * mode.frequency_hz;
    const double omega = omega_si * model.units().time;
    const double lambda = omega * omega;
    weighted.setZero();
    double power = 1.0;
    for (int j = 0; j <= model.SeriesOrder(); ++j, power *= lambda) {
      model.Mass(j).Multiply(mode.shape, product);
      weighted += (j + 1) * power * product;
    }
    out.shapes.col(static_cast<Eigen::Index>(i)) = mode.shape / std::sqrt(mode.shape.dot(weighted));
    out.coordinates.push_back({omega, damping.ModalRatio(omega_si)});
  }
  return out;
}

}  // namespace cosmems
