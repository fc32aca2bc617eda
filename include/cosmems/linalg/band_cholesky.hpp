#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_kernels.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// Cholesky factorisation A = L L^T of a symmetric positive definite band matrix, in the band's
/// own storage: O(n b^2) to factor and O(n b) to solve, against O(n^3) and O(n^2) dense.
///
/// Eigen's idiom: Compute(), info(), Solve(). A pivot that falls below a relative threshold of
/// its diagonal entry means the matrix is singular to working precision (a beam that is not
/// supported against a rigid motion): info() reports it and no factor is kept.
class BandCholesky {
 public:
  BandCholesky() = default;
  explicit BandCholesky(const SymmetricBandMatrix& a) { Compute(a); }

  BandCholesky& Compute(const SymmetricBandMatrix& a) {
    const int n = a.size();
    const int bw = a.bandwidth();
    factor_ = a.data();
    inverse_diagonal_.resize(n);
    size_ = n;
    bandwidth_ = bw;
    status_ = Status::kOk;
    // A pivot this far below its original diagonal is round-off of a singular matrix; a
    // supported beam of 10^4 elements stays many decades above it.
    constexpr double kPivotFloor = 64.0 * std::numeric_limits<double>::epsilon();
    for (int j = 0; j < n; ++j) {
      const int first = std::max(0, j - bw);
      double d = factor_(0, j);
      for (int k = first; k < j; ++k) d -= factor_(j - k, k) * factor_(j - k, k);
      if (!(d > kPivotFloor * a.data()(0, j)) || !std::isfinite(d)) {
        status_ = std::isfinite(d) ? Status::kNotPositiveDefinite : Status::kNonFinite;
        return *this;
      }
      const double ljj = std::sqrt(d);
      factor_(0, j) = ljj;
      inverse_diagonal_[j] = 1.0 / ljj;
      const int last = std::min(n - 1, j + bw);
      for (int i = j + 1; i <= last; ++i) {
        double s = factor_(i - j, j);
        for (int k = std::max(0, i - bw); k < j; ++k) s -= factor_(i - k, k) * factor_(j - k, k);
        factor_(i - j, j) = s / ljj;
      }
    }
    // Fold the pivots into the factor for the solves (see internal::BandCholeskySolve).
    forward_ = factor_;
    backward_ = factor_;
    for (int j = 0; j < n; ++j) {
      for (int k = 1; k <= std::min(bw, n - 1 - j); ++k) {
        forward_(k, j) *= inverse_diagonal_[j + k];
        backward_(k, j) *= inverse_diagonal_[j];
      }
    }
    return *this;
  }

  Status info() const { return status_; }
  int size() const { return size_; }

  /// Solves A x = b in place. Allocates nothing; call only when info() is kOk.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    const int stride = static_cast<int>(forward_.rows());
    const bool fixed = internal::DispatchBandwidth(bandwidth_, [&](auto w) {
      internal::BandCholeskySolve<decltype(w)::value>(forward_.data(), backward_.data(), stride,
                                                      inverse_diagonal_.data(), size_, b.data());
    });
    if (fixed) return;
    for (int i = 0; i < size_; ++i) {  // L y = b
      double s = b[i] * inverse_diagonal_[i];
      for (int k = std::min(bandwidth_, i); k >= 1; --k) s -= forward_(k, i - k) * b[i - k];
      b[i] = s;
    }
    for (int j = size_ - 1; j >= 0; --j) {  // L^T x = y
      double s = b[j] * inverse_diagonal_[j];
      for (int k = std::min(bandwidth_, size_ - 1 - j); k >= 1; --k)
        s -= backward_(k, j) * b[j + k];
      b[j] = s;
    }
  }

  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x = b;
    SolveInPlace(x);
    return x;
  }

 private:
  Eigen::MatrixXd factor_;
  Eigen::MatrixXd forward_;   ///< L(i, i-k) / L(i, i)
  Eigen::MatrixXd backward_;  ///< L(j+k, j) / L(j, j)
  Eigen::VectorXd inverse_diagonal_;
  int size_ = 0;
  int bandwidth_ = 0;
  Status status_ = Status::kNotPositiveDefinite;
};

}  // namespace cosmems
