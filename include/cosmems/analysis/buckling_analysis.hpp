#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_cholesky.hpp"

namespace cosmems {

struct BucklingOptions {
  int count = 1;             ///< buckling modes wanted, lowest load first
  double tolerance = 1e-12;  ///< relative change of every wanted load between sweeps
  /// ||K_L x - mu G_0 x|| <= residual_tolerance * mu ||G_0 x|| for every wanted mode.
  double residual_tolerance = 1e-9;
  int max_iterations = 500;
};

struct BucklingMode {
  double critical_load_n = 0.0;  ///< compressive axial force at which this mode buckles (N)
  Eigen::VectorXd shape;         ///< reduced, internal units, largest entry +1
};

struct BucklingResult {
  Status status = Status::kOk;
  std::vector<BucklingMode> modes;  ///< ascending critical load
  int iterations = 0;
};

/// The lowest positive eigenvalues mu of (K - mu G) x = 0, each mode's critical_load_n set to
/// mu times `scale`: the loads at which the geometric stiffness G cancels the elastic K.
///
/// Subspace iteration on K^-1 G (one band back-solve per vector and sweep) with Rayleigh-Ritz on
/// the projected pencil (Q^T G Q, Q^T K Q), whose largest eigenvalues are 1/mu; mode i converges
/// as mu_i / mu_(q+1) per sweep. G may be semi-definite (a beam's axial and torsion fields carry
/// none) or indefinite (a frame's members in tension), so the pencil is solved with K, which is
/// definite, on the right; no positive 1/mu left means nothing buckles (kNotConverged).
inline BucklingResult SolveBucklingPencil(const SymmetricBandMatrix& k,
                                          const SymmetricBandMatrix& g, double scale,
                                          const BucklingOptions& options = {}) {
  BucklingResult result;
  const int n = k.size();
  // K_L^-1 G_0 X has no larger rank than the degrees of freedom G_0 acts on: a subspace wider
  // than that (all 3 unknowns of a 1-element cantilever, 2 of them bending) leaves the projected
  // K_L singular.
  int bending = 0;
  for (int i = 0; i < n; ++i) bending += g(i, i) != 0.0;
  const int p = std::min(options.count, bending);
  const int q = std::min(bending, std::max(2 * p, p + 8));
  if (p <= 0) return result;
  const BandCholesky cholesky(k);
  result.status = cholesky.info();
  if (result.status != Status::kOk) return result;

  std::mt19937 random(20261121u);  // fixed seed: reproducible runs
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd x = Eigen::MatrixXd::NullaryExpr(n, q, [&]() { return uniform(random); });
  Eigen::MatrixXd gx(n, q), y(n, q);
  Eigen::VectorXd mu = Eigen::VectorXd::Zero(p);
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(p, -1.0);
  result.status = Status::kNotConverged;
  for (result.iterations = 1; result.iterations <= options.max_iterations; ++result.iterations) {
    for (int i = 0; i < q; ++i) {
      auto gx_i = gx.col(i);
      g.Multiply(x.col(i), gx_i);
      y.col(i) = gx_i;
      cholesky.SolveInPlace(y.col(i));
    }
    // Y = Q R with K Y = G X exactly, so Q^T K Q = Q^T G X R^-1 needs no product with K.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(y);
    const Eigen::MatrixXd basis = qr.householderQ() * Eigen::MatrixXd::Identity(n, q);
    const Eigen::MatrixXd r = qr.matrixQR().topRows(q).triangularView<Eigen::Upper>();
    Eigen::MatrixXd kr =
        r.transpose().triangularView<Eigen::Lower>().solve((basis.transpose() * gx).transpose());
    kr = (0.5 * (kr + kr.transpose())).eval();
    Eigen::MatrixXd gq(n, q);
    for (int i = 0; i < q; ++i) {
      auto gq_i = gq.col(i);
      g.Multiply(basis.col(i), gq_i);
    }
    Eigen::MatrixXd gr = basis.transpose() * gq;
    gr = (0.5 * (gr + gr.transpose())).eval();
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> pencil(gr, kr);
    if (pencil.info() != Eigen::Success) {
      result.status = Status::kNotConverged;
      return result;
    }
    // Largest 1/mu last: reverse so that the lowest critical load comes first.
    const Eigen::MatrixXd z = pencil.eigenvectors().rowwise().reverse();
    x = basis * z;
    // K x from K Y = G X as well: a product with K would cancel for smooth x.
    const Eigen::MatrixXd kx = gx * r.triangularView<Eigen::Upper>().solve(z.leftCols(p));
    bool converged = true;
    Eigen::VectorXd gxi(n);
    for (int i = 0; i < p; ++i) {
      const double inverse = pencil.eigenvalues()[q - 1 - i];
      if (!(inverse > 0.0)) {  // G_0 has no positive direction left: nothing buckles
        result.status = Status::kNotConverged;
        return result;
      }
      mu[i] = 1.0 / inverse;
      g.Multiply(x.col(i), gxi);
      converged =
          converged && std::abs(mu[i] - previous[i]) <= options.tolerance * mu[i] &&
          (kx.col(i) - mu[i] * gxi).norm() <= options.residual_tolerance * mu[i] * gxi.norm();
    }
    previous = mu;
    if (converged) {
      result.status = Status::kOk;
      break;
    }
  }
  result.iterations = std::min(result.iterations, options.max_iterations);
  for (int i = 0; i < p; ++i) {
    Eigen::VectorXd shape = x.col(i);
    Eigen::Index largest = 0;
    shape.cwiseAbs().maxCoeff(&largest);
    shape /= shape[largest];
    result.modes.push_back({mu[i] * scale, std::move(shape)});
  }
  return result;
}

/// The critical compressive loads of a straight beam: (K_L - mu G_0) x = 0, the axial force
/// N = -mu at which the geometric stiffness cancels the elastic one. The loads do not depend on
/// the description's own axial_load: they are the total compressive force the beam can carry.
template <int Dim>
BucklingResult SolveBuckling(const BeamModel<Dim>& model, const BucklingOptions& options = {}) {
  return SolveBucklingPencil(model.ElasticStiffness(), model.Geometric(0), model.units().force,
                             options);
}

}  // namespace cosmems
