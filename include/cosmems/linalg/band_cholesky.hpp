#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_kernels.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// Cholesky factorisation of a symmetric positive definite band matrix in its square-root-free
/// form A = L D L^T (L unit lower), in the band's own storage: O(n b^2) to factor and O(n b) to
/// solve, against O(n^3) and O(n^2) dense. Square-root-free, the factor comes out in the form
/// the solves use, with no later pass to fold an L L^T factor's pivots in, and it factors faster
/// for that (doc/speed.md, "Kernel choices").
///
/// Eigen's idiom: Compute(), info(), Solve(). A pivot that falls below a relative threshold of
/// its diagonal entry means the matrix is singular to working precision (a beam that is not
/// supported against a rigid motion): info() reports it and no factor is kept.
class BandCholesky {
 public:
  BandCholesky() = default;
  explicit BandCholesky(const SymmetricBandMatrix& a) { Compute(a); }

  /// Allocates nothing when the last factor had the same size and bandwidth (a Newton
  /// iteration).
  BandCholesky& Compute(const SymmetricBandMatrix& a) {
    const int n = a.size();
    const int bw = a.bandwidth();
    unit_.resize(bw + 1, n);
    pivot_.resize(n);
    inverse_pivot_.resize(n);
    size_ = n;
    bandwidth_ = bw;
    int failed = n;
    // The beams' bandwidths, fixed at compile time so that the loops unroll.
    const bool fixed = internal::DispatchBandwidth(bw, [&](auto w) {
      failed = internal::BandLdlFactor<decltype(w)::value>(a.data().data(), bw + 1, n, kPivotFloor,
                                                           unit_.data(), pivot_.data(),
                                                           inverse_pivot_.data());
    });
    if (!fixed) failed = FactorAnyBandwidth(a);
    if (failed == n) {
      status_ = Status::kOk;
    } else {
      status_ = std::isfinite(pivot_[failed]) ? Status::kNotPositiveDefinite : Status::kNonFinite;
    }
    return *this;
  }

  Status info() const { return status_; }
  int size() const { return size_; }
  int bandwidth() const { return bandwidth_; }

  /// Solves A x = b in place. Allocates nothing; call only when info() is kOk.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    const int stride = bandwidth_ + 1;
    const bool fixed = internal::DispatchBandwidth(bandwidth_, [&](auto w) {
      internal::BandLdlSolve<decltype(w)::value>(unit_.data(), stride, inverse_pivot_.data(), size_,
                                                 b.data());
    });
    if (fixed) return;
    for (int i = 0; i < size_; ++i) {  // L y = b
      double s = b[i];
      for (int k = std::min(bandwidth_, i); k >= 1; --k) s -= unit_(k, i - k) * b[i - k];
      b[i] = s;
    }
    for (int j = size_ - 1; j >= 0; --j) {  // L^T x = D^-1 y
      double s = b[j] * inverse_pivot_[j];
      for (int k = std::min(bandwidth_, size_ - 1 - j); k >= 1; --k) s -= unit_(k, j) * b[j + k];
      b[j] = s;
    }
  }

  /// Solves A x = b in place with b's entries made row by row, b_i = rhs(i), and each solved x_j
  /// handed to solved(j, x_j) (internal::BandLdlSolveRows: work independent of the sweeps runs in
  /// their waits), W the bandwidth() fixed at compile time. Allocates nothing; call only when
  /// info() is kOk.
  template <int W, typename Rhs, typename Solved>
  void SolveRows(double* b, Rhs&& rhs, Solved&& solved) const {
    assert(W == bandwidth_);
    internal::BandLdlSolveRows<W>(unit_.data(), W + 1, inverse_pivot_.data(), size_, b,
                                  std::forward<Rhs>(rhs), std::forward<Solved>(solved));
  }

  /// Solves A x = b and A y = c in place, together: the sweeps wait on the row before, and the
  /// second system fills those waits. Allocates nothing; call only when info() is kOk.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b, Eigen::Ref<Eigen::VectorXd> c) const {
    const int stride = bandwidth_ + 1;
    const bool fixed = internal::DispatchBandwidth(bandwidth_, [&](auto w) {
      internal::BandLdlSolve2<decltype(w)::value>(unit_.data(), stride, inverse_pivot_.data(),
                                                  size_, b.data(), c.data());
    });
    if (fixed) return;
    SolveInPlace(b);
    SolveInPlace(c);
  }

  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x = b;
    SolveInPlace(x);
    return x;
  }

  /// The entries of A^-1 within A's band (a selected inverse: Takahashi, Fagan & Chin 1973), by
  /// the recurrence Z = D^-1 L^-1 + (I - L^T) Z from the last row up, which reads Z only within
  /// the band: O(n b^2), where the whole inverse costs O(n^2 b). A quadratic form w^T A^-1 w
  /// needs no more when w's entries lie within the band of each other, as a load spread over
  /// one element's or one body's unknowns does. Allocates the result; call only when info() is
  /// kOk.
  SymmetricBandMatrix InverseWithinBand() const {
    const int n = size_, bw = bandwidth_;
    SymmetricBandMatrix inverse(n, bw);
    Eigen::MatrixXd& z = inverse.mutable_data();  // Z(i + k, i) at z(k, i)
    for (int i = n - 1; i >= 0; --i) {
      const int last = std::min(n - 1, i + bw);
      for (int j = last; j > i; --j) {  // Z(j, i) = -sum_k L(k, i) Z(k, j), k in (i, last]
        double s = 0.0;
        for (int k = i + 1; k <= last; ++k) {
          s -= unit_(k - i, i) * (k >= j ? z(k - j, j) : z(j - k, k));
        }
        z(j - i, i) = s;
      }
      double s = inverse_pivot_[i];
      for (int k = i + 1; k <= last; ++k) s -= unit_(k - i, i) * z(k - i, i);
      z(0, i) = s;
    }
    return inverse;
  }

 private:
  // A pivot this far below its original diagonal is round-off of a singular matrix; a supported
  // beam of 10^4 elements stays many decades above it.
  static constexpr double kPivotFloor = 64.0 * std::numeric_limits<double>::epsilon();

  // internal::BandLdlFactor for a bandwidth known only at run time; returns the failed column
  // or n.
  int FactorAnyBandwidth(const SymmetricBandMatrix& a) {
    const int n = size_, bw = bandwidth_;
    for (int j = 0; j < n; ++j) {
      double d = a.data()(0, j);
      for (int k = 1; k <= std::min(j, bw); ++k)
        d -= unit_(k, j - k) * unit_(k, j - k) * pivot_[j - k];
      pivot_[j] = d;
      if (!(d > kPivotFloor * a.data()(0, j)) || !std::isfinite(d)) return j;
      inverse_pivot_[j] = 1.0 / d;
      unit_(0, j) = 1.0;
      for (int r = 1; r <= bw; ++r) {
        if (j + r >= n) {
          unit_(r, j) = 0.0;
          continue;
        }
        double s = a.data()(r, j);
        for (int k = 1; k <= std::min(j, bw - r); ++k)
          s -= unit_(k + r, j - k) * unit_(k, j - k) * pivot_[j - k];
        unit_(r, j) = s * inverse_pivot_[j];
      }
    }
    return n;
  }

  Eigen::MatrixXd unit_;  ///< L(j+k, j) at (k, j), L's unit diagonal in row 0
  Eigen::VectorXd pivot_;
  Eigen::VectorXd inverse_pivot_;
  int size_ = 0;
  int bandwidth_ = 0;
  Status status_ = Status::kNotPositiveDefinite;
};

}  // namespace cosmems
