#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// A = L D L^T of a symmetric band matrix that need not be definite, without pivoting, and its
/// inertia: the number of negative pivots is the number of negative eigenvalues (Sylvester's law),
/// which tells a stable equilibrium from an unstable one. Without pivoting the factorisation
/// exists when every leading minor is regular; a pivot below a relative 1e-13 of its diagonal
/// entry is reported as singular. Meant for the matrices a positive definite one becomes past a
/// limit point (a few negative eigenvalues), where BandCholesky stops. Compute() and
/// SolveInPlace() allocate nothing once sized.
class BandLdlt {
 public:
  Status Compute(const SymmetricBandMatrix& a) {
    const int n = a.size(), w = a.bandwidth();
    factor_ = a.data();  // L below the diagonal row, D on it
    size_ = n;
    bandwidth_ = w;
    negative_ = 0;
    for (int j = 0; j < n; ++j) {
      double d = factor_(0, j);
      for (int k = std::max(0, j - w); k < j; ++k) {
        const double l = factor_(j - k, k);
        d -= l * l * factor_(0, k);
      }
      if (!std::isfinite(d)) return status_ = Status::kNonFinite;
      if (std::abs(d) <= 1e-13 * std::abs(a.data()(0, j))) {
        return status_ = Status::kNotPositiveDefinite;
      }
      factor_(0, j) = d;
      if (d < 0.0) ++negative_;
      for (int i = j + 1; i <= std::min(n - 1, j + w); ++i) {
        double s = factor_(i - j, j);
        for (int k = std::max(0, i - w); k < j; ++k) {
          s -= factor_(i - k, k) * factor_(j - k, k) * factor_(0, k);
        }
        factor_(i - j, j) = s / d;
      }
    }
    return status_ = Status::kOk;
  }

  Status info() const { return status_; }
  /// Negative pivots: the matrix's negative eigenvalues.
  int negative_pivots() const { return negative_; }

  /// b <- A^-1 b. Allocates nothing.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    for (int i = 0; i < size_; ++i) {
      for (int k = std::max(0, i - bandwidth_); k < i; ++k) b[i] -= factor_(i - k, k) * b[k];
    }
    for (int i = 0; i < size_; ++i) b[i] /= factor_(0, i);
    for (int i = size_ - 1; i >= 0; --i) {
      for (int k = i + 1; k <= std::min(size_ - 1, i + bandwidth_); ++k) {
        b[i] -= factor_(k - i, i) * b[k];
      }
    }
  }

 private:
  Eigen::MatrixXd factor_;
  int size_ = 0;
  int bandwidth_ = 0;
  int negative_ = 0;
  Status status_ = Status::kOk;
};

}  // namespace cosmems
