#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/linalg/band_kernels.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// A symmetric band matrix expanded to full rows, A(i, i-W) ... A(i, i+W) contiguous and zero
/// outside the matrix, for the products of a time step. Against a vector padded with W zeros at
/// both ends, row i's product is one fixed-length contiguous dot product, which vectorises. It
/// beat the band storage's row-by-row product; that storage's product by columns
/// (SymmetricBandMatrix) has since caught up (doc/speed.md, "Kernel choices").
class BandRows {
 public:
  BandRows() = default;
  explicit BandRows(const SymmetricBandMatrix& a)
      : size_(a.size()),
        bandwidth_(a.bandwidth()),
        rows_(static_cast<std::size_t>(a.size()) * Width()) {
    for (int i = 0; i < size_; ++i) {
      for (int k = -bandwidth_; k <= bandwidth_; ++k) {
        if (i + k >= 0 && i + k < size_)
          rows_[static_cast<std::size_t>(i) * Width() + k + bandwidth_] = a(i, i + k);
      }
    }
  }

  int size() const { return size_; }
  /// The zeros a vector needs before and after its entries.
  int padding() const { return bandwidth_; }
  int Width() const { return 2 * bandwidth_ + 1; }

  /// Row i of A x, `x_padded` holding x at offsets padding() ... padding() + size() - 1 and zeros
  /// around it, for the bandwidth W fixed at compile time (W == padding()).
  template <int W>
  double RowProduct(int i, const double* x_padded) const {
    using Row = Eigen::Matrix<double, 2 * W + 1, 1>;
    return Eigen::Map<const Row>(rows_.data() + static_cast<long>(i) * (2 * W + 1))
        .dot(Eigen::Map<const Row>(x_padded + i));
  }

  /// y -= A x, x padded as for RowProduct(). Allocates nothing.
  void SubtractProduct(const double* x_padded, double* y) const {
    const bool fixed = internal::DispatchBandwidth(bandwidth_, [&](auto w) {
      for (int i = 0; i < size_; ++i) y[i] -= RowProduct<decltype(w)::value>(i, x_padded);
    });
    if (fixed) return;
    const int width = Width();
    for (int i = 0; i < size_; ++i) {
      double sum = 0.0;
      for (int k = 0; k < width; ++k)
        sum += rows_[static_cast<std::size_t>(i) * width + k] * x_padded[i + k];
      y[i] -= sum;
    }
  }

 private:
  int size_ = 0;
  int bandwidth_ = 0;
  std::vector<double> rows_;
};

}  // namespace cosmems
