#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include <Eigen/Dense>

#include "cosmems/analysis/mode_kind.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/core/constants.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_cholesky.hpp"

namespace cosmems {

namespace internal {

/// The Rayleigh functional of a symmetric polynomial eigenproblem: the root l near `estimate`
/// of z^T (Kr - sum_j l^(j+1) Mr_j) z = 0, by Newton. Its error is quadratic in the error of z,
/// so it removes the round-off that the nonsymmetric companion solve leaves in l.
inline double RayleighFunctional(const Eigen::MatrixXd& kr, const std::vector<Eigen::MatrixXd>& mr,
                                 const Eigen::Ref<const Eigen::VectorXd>& z, double estimate) {
  const double a = z.dot(kr * z);
  std::vector<double> b;
  for (const Eigen::MatrixXd& m : mr) b.push_back(z.dot(m * z));
  double l = estimate;
  for (int iteration = 0; iteration < 20; ++iteration) {
    double f = a;
    double df = 0.0;
    double power = 1.0;  // l^j
    for (std::size_t j = 0; j < b.size(); ++j) {
      df -= static_cast<double>(j + 1) * b[j] * power;
      power *= l;
      f -= b[j] * power;
    }
    const double step = f / df;
    l -= step;
    if (!(std::abs(step) > 1e-16 * std::abs(l))) break;
  }
  return std::isfinite(l) ? l : estimate;
}

/// Solves the projected polynomial eigenproblem (Kr - sum_j l^(j+1) Mr_j) z = 0 through its
/// companion linearisation in mu = 1/l: [Kr^-1 Mr_0 ... Kr^-1 Mr_k; I 0 ...; ...]. Returns the
/// real, positive roots in ascending l (at most Kr's size of them) and their vectors.
inline void SolveProjectedPolynomial(const Eigen::MatrixXd& kr, const std::vector<Eigen::MatrixXd>& mr,
                                     Eigen::VectorXd& lambda, Eigen::MatrixXd& z) {
  const Eigen::Index q = kr.rows();
  const Eigen::Index terms = static_cast<Eigen::Index>(mr.size());
  const Eigen::LLT<Eigen::MatrixXd> llt(kr);
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(terms * q, terms * q);
  for (Eigen::Index j = 0; j < terms; ++j) companion.block(0, j * q, q, q) = llt.solve(mr[j]);
  companion.bottomLeftCorner((terms - 1) * q, (terms - 1) * q).setIdentity();
  const Eigen::EigenSolver<Eigen::MatrixXd> eig(companion);
  const Eigen::VectorXcd mu = eig.eigenvalues();

  std::vector<Eigen::Index> real_roots;
  for (Eigen::Index i = 0; i < mu.size(); ++i) {
    // The physical roots are real; an imaginary part at round-off level is noise.
    if (mu[i].real() > 0.0 && std::abs(mu[i].imag()) <= 1e-8 * std::abs(mu[i])) {
      real_roots.push_back(i);
    }
  }
  std::sort(real_roots.begin(), real_roots.end(),
            [&](Eigen::Index a, Eigen::Index b) { return mu[a].real() > mu[b].real(); });
  const Eigen::Index count = std::min<Eigen::Index>(q, static_cast<Eigen::Index>(real_roots.size()));
  lambda.setZero(q);
  z.resize(q, count);
  const Eigen::MatrixXcd vectors = eig.eigenvectors();
  for (Eigen::Index i = 0; i < count; ++i) {
    const double estimate = 1.0 / mu[real_roots[i]].real();
    // A complex eigenvector of a real root carries an arbitrary phase: rotate it real first.
    Eigen::VectorXcd v = vectors.col(real_roots[i]).head(q);
    Eigen::Index largest = 0;
    v.cwiseAbs().maxCoeff(&largest);
    v *= std::conj(v[largest]) / std::abs(v[largest]);
    z.col(i) = v.real().normalized();
    lambda[i] = RayleighFunctional(kr, mr, z.col(i), estimate);
  }
}

}  // namespace internal

struct ModalOptions {
  int count = 4;                ///< modes wanted, lowest first
  double tolerance = 1e-12;     ///< relative change of every wanted eigenvalue between sweeps
  int max_iterations = 500;     ///< sweeps before giving up with Status::kNotConverged
};

struct Mode {
  double frequency_hz = 0.0;
  ModeKind kind = ModeKind::kBendingY;
  Eigen::VectorXd shape;  ///< reduced, internal units, x^T M_0 x = 1, largest entry positive
};

struct ModalResult {
  Status status = Status::kOk;
  std::vector<Mode> modes;  ///< ascending frequency
  int iterations = 0;
};

/// The lowest natural frequencies and modes of a beam.
///
/// Order 0 solves K x = w^2 M_0 x. Order k >= 1 solves the polynomial eigenproblem
/// (K - l M_0 - l^2 M_2 - ... - l^(k+1) M_2k) x = 0 in l = w^2 of the power-series elements.
/// Both go by subspace iteration with Rayleigh-Ritz: each sweep applies K^-1 (one band back-
/// solve per vector) to sum_j l_i^j M_2j x_i, the fixed point of x = l K^-1 sum_j l^j M_2j x, then
/// projects onto the swept basis. The projected polynomial problem is linearised in companion
/// form for mu = 1 / l and solved densely (it is a few dozen wide); its largest real mu are the
/// wanted modes, while the spurious roots a truncated series adds lie far up the spectrum.
/// Convergence of mode i goes as l_i / l_(q+1) per sweep with q = max(2p, p + 8) vectors.
template <int Dim>
ModalResult SolveModal(const BeamModel<Dim>& model, const ModalOptions& options = {}) {
  ModalResult result;
  const int n = model.FreeDofCount();
  const int p = std::min(options.count, n);
  const int q = std::min(n, std::max(2 * p, p + 8));
  const int order = model.SeriesOrder();
  if (p <= 0) return result;

  const BandCholesky cholesky(model.Stiffness());
  result.status = cholesky.info();
  if (result.status != Status::kOk) return result;

  std::mt19937 random(20261121u);  // fixed seed: reproducible runs
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd x = Eigen::MatrixXd::NullaryExpr(n, q, [&]() { return uniform(random); });
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(q);
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(q, -1.0);
  Eigen::MatrixXd y(n, q), ky(n, q), column(n, 1);
  std::vector<Eigen::MatrixXd> my(order + 1, Eigen::MatrixXd(n, q));
  Eigen::VectorXd rhs(n), tmp(n);

  for (result.iterations = 1; result.iterations <= options.max_iterations; ++result.iterations) {
    for (int i = 0; i < q; ++i) {  // y_i = K^-1 sum_j l_i^j M_2j x_i
      rhs.setZero();
      double power = 1.0;
      for (int j = 0; j <= order; ++j, power *= lambda[i]) {
        model.Mass(j).Multiply(x.col(i), tmp);
        rhs += power * tmp;
      }
      cholesky.SolveInPlace(rhs);
      y.col(i) = rhs;
    }
    y = Eigen::HouseholderQR<Eigen::MatrixXd>(y).householderQ() * Eigen::MatrixXd::Identity(n, q);
    for (int i = 0; i < q; ++i) {
      auto out = ky.col(i);
      model.Stiffness().Multiply(y.col(i), out);
      for (int j = 0; j <= order; ++j) {
        auto m_out = my[j].col(i);
        model.Mass(j).Multiply(y.col(i), m_out);
      }
    }
    const Eigen::MatrixXd kr = y.transpose() * ky;
    std::vector<Eigen::MatrixXd> mr;
    for (int j = 0; j <= order; ++j) mr.push_back(y.transpose() * my[j]);

    Eigen::MatrixXd z;
    if (order == 0) {
      Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(
          0.5 * (kr + kr.transpose()), 0.5 * (mr[0] + mr[0].transpose()));
      lambda = eig.eigenvalues();
      z = eig.eigenvectors();
    } else {
      internal::SolveProjectedPolynomial(kr, mr, lambda, z);
    }
    x.leftCols(z.cols()) = y * z;
    if (z.cols() < q) {  // keep the basis full when fewer real roots were found
      x.rightCols(q - z.cols()) = y.rightCols(q - z.cols());
      lambda.tail(q - z.cols()).setZero();
    }

    bool converged = z.cols() >= p;
    for (int i = 0; i < p && converged; ++i) {
      converged = std::abs(lambda[i] - previous[i]) <= options.tolerance * std::abs(lambda[i]);
    }
    previous = lambda;
    if (converged) break;
  }
  if (result.iterations > options.max_iterations) {
    result.status = Status::kNotConverged;
    result.iterations = options.max_iterations;
  }

  for (int i = 0; i < p; ++i) {
    Mode mode;
    Eigen::VectorXd shape = x.col(i);
    shape /= std::sqrt(shape.dot(model.Mass(0) * shape));
    Eigen::Index largest = 0;
    shape.cwiseAbs().maxCoeff(&largest);
    if (shape[largest] < 0.0) shape = -shape;
    mode.frequency_hz = std::sqrt(lambda[i]) / (2.0 * kPi * model.units().time);
    mode.kind = ClassifyMode(model, shape);
    mode.shape = std::move(shape);
    if (!std::isfinite(mode.frequency_hz)) result.status = Status::kNonFinite;
    result.modes.push_back(std::move(mode));
  }
  return result;
}

}  // namespace cosmems
