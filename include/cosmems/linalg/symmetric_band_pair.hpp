#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/linalg/band_kernels.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// Two symmetric band matrices of one size and bandwidth (a structure's mass and stiffness),
/// held entry by entry side by side, so that A x and B z are formed in one pass: each paired
/// operation does both products' work, which the scalar kernel does one at a time. The results
/// equal A.Multiply(x) and B.Multiply(z) to the bit (each lane takes the same operations in the
/// same order), for a bandwidth without a fixed kernel too (the same run-time-bandwidth kernel). A
/// copy: later changes to A or B do not reach it.
class SymmetricBandPair {
 public:
  SymmetricBandPair(const SymmetricBandMatrix& a, const SymmetricBandMatrix& b)
      : n_(a.size()), stride_(a.bandwidth() + 1) {
    if (b.size() != a.size() || b.bandwidth() != a.bandwidth()) {
      throw std::invalid_argument("SymmetricBandPair: the matrices differ: size " +
                                  std::to_string(a.size()) + " and " + std::to_string(b.size()) +
                                  ", bandwidth " + std::to_string(a.bandwidth()) + " and " +
                                  std::to_string(b.bandwidth()));
    }
    entries_.resize(static_cast<size_t>(stride_) * n_);
    for (int j = 0; j < n_; ++j) {
      for (int k = 0; k < stride_; ++k) {
        entries_[static_cast<size_t>(j) * stride_ + k] =
            internal::DoublePair{a.data()(k, j), b.data()(k, j)};
      }
    }
    inputs_.resize(n_);
    outputs_.resize(n_);
  }

  /// ax = A x and bz = B z. The inputs are read before the outputs are written, so an output may
  /// be an input. Allocates nothing.
  void Multiply(const Eigen::Ref<const Eigen::VectorXd>& x,
                const Eigen::Ref<const Eigen::VectorXd>& z, Eigen::Ref<Eigen::VectorXd> ax,
                Eigen::Ref<Eigen::VectorXd> bz) {
    for (int i = 0; i < n_; ++i) inputs_[i] = internal::DoublePair{x[i], z[i]};
    const bool fixed = internal::DispatchBandwidth(stride_ - 1, [&](auto w) {
      internal::SymmetricBandMultiplyAdd<decltype(w)::value, false>(
          entries_.data(), stride_, n_, inputs_.data(), 1.0, outputs_.data());
    });
    if (!fixed) {
      for (int i = 0; i < n_; ++i) outputs_[i] = internal::DoublePair{};
      internal::SymmetricBandMultiplyAddAnyWidth(entries_.data(), stride_, n_, stride_ - 1,
                                                 inputs_.data(), 1.0, outputs_.data());
    }
    for (int i = 0; i < n_; ++i) {
      ax[i] = outputs_[i][0];
      bz[i] = outputs_[i][1];
    }
  }

 private:
  int n_ = 0, stride_ = 0;
  std::vector<internal::DoublePair> entries_;
  std::vector<internal::DoublePair> inputs_, outputs_;
};

}  // namespace cosmems
