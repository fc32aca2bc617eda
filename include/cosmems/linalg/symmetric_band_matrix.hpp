#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/linalg/band_kernels.hpp"

namespace cosmems {

/// A symmetric matrix held by its lower band, LAPACK style: entry (i, j) with
/// 0 <= i - j <= bandwidth sits at data(i - j, j). A beam numbered node by node has a band of
/// 2 x (dofs per node) - 1, so storage and work grow linearly with the element count.
class SymmetricBandMatrix {
 public:
  SymmetricBandMatrix() = default;
  SymmetricBandMatrix(int size, int bandwidth)
      : size_(size), bandwidth_(bandwidth), data_(Eigen::MatrixXd::Zero(bandwidth + 1, size)) {}

  int size() const { return size_; }
  int bandwidth() const { return bandwidth_; }
  const Eigen::MatrixXd& data() const { return data_; }
  /// The band storage itself, for combining matrices of one pattern (a M + b K) in one pass.
  Eigen::MatrixXd& mutable_data() { return data_; }

  /// Entry (i, j) for any order of i and j; zero outside the band.
  double operator()(int i, int j) const {
    if (i < j) std::swap(i, j);
    return i - j <= bandwidth_ ? data_(i - j, j) : 0.0;
  }

  /// Adds v to entries (i, j) and (j, i); |i - j| must lie within the band.
  void Add(int i, int j, double v) {
    if (i < j) std::swap(i, j);
    data_(i - j, j) += v;
  }

  /// y = A x. Allocates nothing.
  void Multiply(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y) const {
    const int stride = static_cast<int>(data_.rows());
    const bool fixed = internal::DispatchBandwidth(bandwidth_, [&](auto w) {
      internal::SymmetricBandMultiplyAdd<decltype(w)::value, false>(data_.data(), stride, size_,
                                                                    x.data(), 1.0, y.data());
    });
    if (fixed) return;
    y.setZero();
    MultiplyAdd(x, y);
  }

  /// y += alpha A x. Allocates nothing.
  void MultiplyAdd(const Eigen::Ref<const Eigen::VectorXd>& x, Eigen::Ref<Eigen::VectorXd> y,
                   double alpha = 1.0) const {
    const int stride = static_cast<int>(data_.rows());
    const bool fixed = internal::DispatchBandwidth(bandwidth_, [&](auto w) {
      internal::SymmetricBandMultiplyAdd<decltype(w)::value>(data_.data(), stride, size_, x.data(),
                                                             alpha, y.data());
    });
    if (fixed) return;
    internal::SymmetricBandMultiplyAddAnyWidth(data_.data(), stride, size_, bandwidth_, x.data(),
                                               alpha, y.data());
  }

  /// A bound on the rounding error of a computed A x (2-norm): each of its entries sums at most
  /// m = 2 bandwidth + 1 products, so it errs by at most gamma_m = m u / (1 - m u) times the
  /// same entry of |A| |x| (u = eps / 2; Higham, Accuracy and Stability of Numerical
  /// Algorithms, 3.5). A residual that holds A x cannot be formed more accurately than this:
  /// for a smooth x on a fine mesh A x is a small difference of large products (the fourth
  /// difference of a beam's stiffness), and the bound passes any fixed relative tolerance on A x.
  /// `work` (size()) is overwritten; allocates nothing.
  double ProductRoundOff(const Eigen::Ref<const Eigen::VectorXd>& x,
                         Eigen::Ref<Eigen::VectorXd> work) const {
    AbsoluteProduct(x, work);
    return ProductRoundOffFactor() * work.norm();
  }
  /// gamma_m of ProductRoundOff: its bound is this times || |A| |x| ||.
  double ProductRoundOffFactor() const {
    const double mu = (2 * bandwidth_ + 1) * 0.5 * std::numeric_limits<double>::epsilon();
    return mu / (1.0 - mu);
  }
  /// The largest row sum of |A|, its infinity norm. ProductRoundOff(x) is at most
  /// ProductRoundOffFactor() times this times ||x||: || |A| |x| || <= || |A| ||_2 ||x||, and the
  /// 2-norm of a symmetric matrix is at most its infinity norm. Once this is known, that ceiling
  /// costs no pass over the band.
  double AbsoluteRowSumMax() const {
    Eigen::VectorXd sums(size_);
    AbsoluteProduct(Eigen::VectorXd::Ones(size_), sums);
    return size_ > 0 ? sums.maxCoeff() : 0.0;
  }

  Eigen::VectorXd operator*(const Eigen::VectorXd& x) const {
    Eigen::VectorXd y(size_);
    Multiply(x, y);
    return y;
  }

  Eigen::MatrixXd ToDense() const {
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(size_, size_);
    for (int j = 0; j < size_; ++j) {
      for (int i = j; i <= std::min(size_ - 1, j + bandwidth_); ++i) {
        dense(i, j) = dense(j, i) = data_(i - j, j);
      }
    }
    return dense;
  }

  /// Both triangles, as the general sparse solvers expect.
  Eigen::SparseMatrix<double> ToSparse() const {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(size_) * (2 * bandwidth_ + 1));
    for (int j = 0; j < size_; ++j) {
      for (int i = j; i <= std::min(size_ - 1, j + bandwidth_); ++i) {
        const double a = data_(i - j, j);
        if (a == 0.0) continue;
        entries.emplace_back(i, j, a);
        if (i != j) entries.emplace_back(j, i, a);
      }
    }
    Eigen::SparseMatrix<double> sparse(size_, size_);
    sparse.setFromTriplets(entries.begin(), entries.end());
    return sparse;
  }

 private:
  // out = |A| |x|.
  void AbsoluteProduct(const Eigen::Ref<const Eigen::VectorXd>& x,
                       Eigen::Ref<Eigen::VectorXd> out) const {
    out.setZero();
    for (int j = 0; j < size_; ++j) {
      const double xj = std::abs(x[j]);
      double sum = std::abs(data_(0, j)) * xj;
      const int last = std::min(size_ - 1, j + bandwidth_);
      for (int i = j + 1; i <= last; ++i) {
        const double a = std::abs(data_(i - j, j));
        out[i] += a * xj;
        sum += a * std::abs(x[i]);
      }
      out[j] += sum;
    }
  }

  int size_ = 0;
  int bandwidth_ = 0;
  Eigen::MatrixXd data_;
};

}  // namespace cosmems
