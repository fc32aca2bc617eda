#include "cosmems/analysis/modal_analysis.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

// The modal solvers' dense parts (Eigen's QR and eigensolvers), compiled once here rather than
// in every unit that includes the header.
namespace cosmems {

Eigen::MatrixXd ModalPencil::DenseStiffness() const {
  return stiffness.ToDense() + rank_one_scale * rank_one * rank_one.transpose();
}

namespace internal {

double RayleighFunctional(const Eigen::MatrixXd& kr, const std::vector<Eigen::MatrixXd>& mr,
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

bool SolveProjected(const Eigen::MatrixXd& kr, const std::vector<Eigen::MatrixXd>& mr, int wanted,
                    Eigen::VectorXd& lambda, Eigen::MatrixXd& z) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> linear(kr, mr[0]);
  lambda = linear.eigenvalues();
  z = linear.eigenvectors();
  if (linear.info() != Eigen::Success) return false;
  if (mr.size() == 1) return true;
  bool all_settled = true;
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(kr.rows());
  for (int i = 0; i < wanted; ++i) {
    double l = lambda[i];
    Eigen::VectorXd vector = z.col(i).normalized();
    double previous_step = std::numeric_limits<double>::infinity();
    for (int iteration = 0; iteration < 50; ++iteration) {
      Eigen::MatrixXd p = kr;
      double power = l;
      for (const Eigen::MatrixXd& m : mr) {
        p -= power * m;
        power *= l;
      }
      eig.compute(p);
      Eigen::Index closest = 0;
      (eig.eigenvectors().transpose() * vector).cwiseAbs().maxCoeff(&closest);
      vector = eig.eigenvectors().col(closest);
      const double next = RayleighFunctional(kr, mr, vector, l);
      // Forming P(l) near its root cancels: l jitters once it has converged, by ~1e-15 in a
      // Ritz basis and by up to eps l_max / l_i in the whole space of a coarse mesh (2.8e-13 for
      // mode 1 of 8 elements). A step that no longer halves, well inside the accuracy any use
      // needs, is that jitter.
      const double step = std::abs(next - l);
      const bool settled = step <= 1e-13 * std::abs(next) ||
                           (step >= 0.5 * previous_step && step <= 1e-10 * std::abs(next));
      previous_step = step;
      l = next;
      if (settled) break;
      if (iteration == 49) all_settled = false;
    }
    lambda[i] = l;
    z.col(i) = vector;
  }
  // Ascending, as the order-0 guesses were; a crossing moves only neighbours of nearly equal
  // frequency (an axial mode among bending ones).
  std::vector<int> order(static_cast<std::size_t>(wanted));
  for (int i = 0; i < wanted; ++i) order[static_cast<std::size_t>(i)] = i;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lambda[a] < lambda[b]; });
  const Eigen::VectorXd unsorted_lambda = lambda.head(wanted);
  const Eigen::MatrixXd unsorted_z = z.leftCols(wanted);
  for (int i = 0; i < wanted; ++i) {
    lambda[i] = unsorted_lambda[order[static_cast<std::size_t>(i)]];
    z.col(i) = unsorted_z.col(order[static_cast<std::size_t>(i)]);
  }
  // Two roots that followed their vectors to the same one: one mode was found twice and another
  // lost. Distinct modes are far from parallel in the M_0 inner product (orthogonal at order 0,
  // nearly so above), so half-way is a safe line.
  const Eigen::MatrixXd mz = mr[0] * z.leftCols(wanted);
  for (int i = 0; i < wanted; ++i) {
    for (int j = 0; j < i; ++j) {
      const double cosine =
          z.col(i).dot(mz.col(j)) / std::sqrt(z.col(i).dot(mz.col(i)) * z.col(j).dot(mz.col(j)));
      if (std::abs(cosine) > 0.5) all_settled = false;
    }
  }
  return all_settled;
}

Status SubspaceIteration(const ModalPencil& pencil, const BandRankOneCholesky& cholesky,
                         const ModalOptions& options, int p, int q, Eigen::VectorXd& lambda,
                         Eigen::MatrixXd& x, int& iterations) {
  const int n = pencil.stiffness.size();
  const int order = static_cast<int>(pencil.mass.size()) - 1;
  std::mt19937 random(20261121u);  // fixed seed: reproducible runs
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  x = Eigen::MatrixXd::NullaryExpr(n, q, [&]() { return uniform(random); });
  lambda = Eigen::VectorXd::Zero(q);
  Eigen::VectorXd previous = Eigen::VectorXd::Constant(q, -1.0);
  Eigen::VectorXd residual(n);
  double inertia = 0.0;
  Eigen::MatrixXd y(n, q), b(n, q), my(n, q);
  Eigen::VectorXd rhs(n), tmp(n);

  for (iterations = 1; iterations <= options.max_iterations; ++iterations) {
    for (int i = 0; i < q; ++i) {  // b_i = sum_j l_i^j M_2j x_i, y_i = K^-1 b_i
      auto b_i = b.col(i);
      b_i.setZero();
      double power = 1.0;
      for (int j = 0; j <= order; ++j, power *= lambda[i]) {
        pencil.mass[j].Multiply(x.col(i), tmp);
        b_i += power * tmp;
      }
      rhs = b_i;
      cholesky.SolveInPlace(rhs);
      y.col(i) = rhs;
    }
    // Orthonormalise Y = Q R. Since K Y = B exactly, Q^T K Q = Q^T B R^-1: projecting K this
    // way avoids the cancellation of forming K Q for smooth vectors, which otherwise leaves a
    // relative error of eps * l_max / l_1 in the lowest eigenvalues of a fine mesh.
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(y);
    y = qr.householderQ() * Eigen::MatrixXd::Identity(n, q);
    const Eigen::MatrixXd r = qr.matrixQR().topRows(q).triangularView<Eigen::Upper>();
    const Eigen::MatrixXd w = y.transpose() * b;
    Eigen::MatrixXd kr =
        r.transpose().triangularView<Eigen::Lower>().solve(w.transpose()).transpose();
    kr = 0.5 * (kr + kr.transpose()).eval();
    std::vector<Eigen::MatrixXd> mr;
    for (int j = 0; j <= order; ++j) {
      for (int i = 0; i < q; ++i) {
        auto out = my.col(i);
        pencil.mass[j].Multiply(y.col(i), out);
      }
      mr.push_back(y.transpose() * my);
      mr.back() = 0.5 * (mr.back() + mr.back().transpose()).eval();
    }

    Eigen::MatrixXd z;
    const bool settled = SolveProjected(kr, mr, p, lambda, z);
    x = y * z;

    // Converged when every wanted eigenvalue has settled and its Ritz pair has a small
    // residual r = K x - sum_j l^(j+1) M_2j x. K x comes from K Y = B (no product with K, so no
    // cancellation for smooth x); a residual, unlike the change of a vector, also settles for
    // repeated eigenvalues, whose vectors may turn freely within their eigenspace.
    const Eigen::MatrixXd k_ritz = b * r.triangularView<Eigen::Upper>().solve(z.leftCols(p));
    bool converged = true;
    for (int i = 0; i < p && converged; ++i) {
      converged = std::abs(lambda[i] - previous[i]) <= options.tolerance * std::abs(lambda[i]);
      residual = k_ritz.col(i);
      double power = lambda[i];
      for (int j = 0; j <= order; ++j, power *= lambda[i]) {
        pencil.mass[j].Multiply(x.col(i), tmp);
        if (j == 0) inertia = std::abs(power) * tmp.norm();
        residual -= power * tmp;
      }
      converged = converged && residual.norm() <= options.residual_tolerance * inertia;
    }
    previous = lambda;
    if (converged && settled) return Status::kOk;
  }
  iterations = options.max_iterations;
  return Status::kNotConverged;
}

}  // namespace internal

ModalResult SolvePencilModes(const ModalPencil& pencil, double time_unit,
                             const ModalOptions& options) {
  ModalResult result;
  const int n = pencil.stiffness.size();
  const int p = std::min(options.count, n);
  const int q = std::min(n, std::max(2 * p, p + 8));
  if (p <= 0) return result;

  BandRankOneCholesky cholesky;
  result.status = cholesky.Compute(pencil.stiffness, pencil.rank_one_scale, pencil.rank_one);
  if (result.status != Status::kOk) return result;

  Eigen::MatrixXd x;
  Eigen::VectorXd lambda;
  if (2 * q >= n) {
    // The subspace would span half the space or more: solve the whole problem densely (n is
    // at most a few dozen here), where subspace iteration would only lose the upper modes.
    std::vector<Eigen::MatrixXd> dense;
    for (const SymmetricBandMatrix& m : pencil.mass) dense.push_back(m.ToDense());
    result.iterations = 1;
    if (!internal::SolveProjected(pencil.DenseStiffness(), dense, p, lambda, x)) {
      result.status = Status::kNotConverged;
    }
  } else {
    result.status =
        internal::SubspaceIteration(pencil, cholesky, options, p, q, lambda, x, result.iterations);
  }
  for (int i = 0; i < p; ++i) {
    Mode mode;
    Eigen::VectorXd shape = x.col(i);
    shape /= std::sqrt(shape.dot(pencil.mass[0] * shape));
    Eigen::Index largest = 0;
    shape.cwiseAbs().maxCoeff(&largest);
    if (shape[largest] < 0.0) shape = -shape;
    mode.frequency_hz = std::sqrt(lambda[i]) / (2.0 * kPi * time_unit);
    mode.shape = std::move(shape);
    if (!std::isfinite(mode.frequency_hz)) result.status = Status::kNonFinite;
    result.modes.push_back(std::move(mode));
  }
  return result;
}

}  // namespace cosmems
