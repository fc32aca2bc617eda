#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/time/modal_propagator.hpp"

namespace cosmems {

/// The modal (multimodal) reduction of a beam or a frame: k modes of its modal analysis, so the
/// power-series order of the model carries into the dynamics. `Model` is a BeamModel or a
/// FrameModel: what is used of it is their common reduced form (FreeDofCount, Stiffness,
/// Mass(j)).
struct ModalModel {
  std::vector<ModalCoordinate> coordinates;  ///< internal units
  Eigen::MatrixXd shapes;                    ///< n x k, unit modal mass

  /// R P = K^-1 P - Phi diag(1/w^2) Phi^T P: what the truncated modes add statically.
  template <class Model>
  Eigen::MatrixXd ResidualFlexibility(const Model& model, const Eigen::MatrixXd& patterns) const {
    const BandCholesky cholesky(model.Stiffness());
    Eigen::MatrixXd r(patterns.rows(), patterns.cols());
    for (Eigen::Index c = 0; c < patterns.cols(); ++c) r.col(c) = cholesky.Solve(patterns.col(c));
    Eigen::VectorXd inverse_w2(coordinates.size());
    for (std::size_t i = 0; i < coordinates.size(); ++i) {
      inverse_w2[i] = 1.0 / (coordinates[i].omega * coordinates[i].omega);
    }
    r -= shapes * inverse_w2.asDiagonal() * (shapes.transpose() * patterns);
    return r;
  }

  /// The modal coordinates q whose displacement Phi q is closest to `d` in the M_0 norm, from
  /// (Phi^T M_0 Phi) q = Phi^T M_0 d (`d` may be a velocity as well). At series order 0 the
  /// shapes are M_0-orthonormal and q = Phi^T M_0 d; at order >= 1 they have unit modal mass in
  /// the polynomial's sense instead, and Phi^T M_0 d alone would weight each mode by its M_0
  /// mass (a released reference cantilever started 1.0002-1.0005 times too deflected with 12-14
  /// modes).
  template <class Model>
  Eigen::VectorXd Project(const Model& model, const Eigen::VectorXd& d) const {
    return Fit(model) * d;
  }

  /// The k x n matrix (Phi^T M_0 Phi)^-1 Phi^T M_0 of Project, for a caller that projects often.
  template <class Model>
  Eigen::MatrixXd Fit(const Model& model) const {
    Eigen::MatrixXd mass_shapes(shapes.rows(), shapes.cols());
    for (Eigen::Index c = 0; c < shapes.cols(); ++c) {
      auto column = mass_shapes.col(c);
      model.Mass(0).Multiply(shapes.col(c), column);
    }
    const Eigen::MatrixXd gram = shapes.transpose() * mass_shapes;
    return gram.llt().solve(mass_shapes.transpose());
  }
};

}  // namespace cosmems
