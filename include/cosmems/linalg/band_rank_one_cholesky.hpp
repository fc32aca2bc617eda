#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// Solves (B + s u u^T) x = b for a symmetric positive definite band B by Sherman-Morrison:
/// x = B^-1 b - w s (u^T B^-1 b) / (1 + s u^T w), w = B^-1 u. One band factorisation and one
/// extra back-solve per Compute(), one back-solve and two dot products per solve, so a
/// stretching beam keeps the cost of a band. Compute() and SolveInPlace() allocate nothing once
/// sized for a given n and bandwidth.
class BandRankOneCholesky {
 public:
  Status Compute(const SymmetricBandMatrix& band, double scale, const Eigen::VectorXd& u) {
    band_.Compute(band);
    if (band_.info() != Status::kOk) return status_ = band_.info();
    scale_ = scale;
    if (scale == 0.0) return status_ = Status::kOk;
    w_ = u;
    band_.SolveInPlace(w_);
    denominator_ = 1.0 + scale * u.dot(w_);
    u_ = u;
    // B + s u u^T is definite exactly when 1 + s u^T B^-1 u > 0 (B definite).
    if (!std::isfinite(denominator_)) return status_ = Status::kNonFinite;
    return status_ = denominator_ > 0.0 ? Status::kOk : Status::kNotPositiveDefinite;
  }

  Status info() const { return status_; }

  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    band_.SolveInPlace(b);
    if (scale_ != 0.0) b -= (scale_ * u_.dot(b) / denominator_) * w_;
  }

 private:
  BandCholesky band_;
  Eigen::VectorXd u_, w_;
  double scale_ = 0.0;
  double denominator_ = 1.0;
  Status status_ = Status::kNotPositiveDefinite;
};

}  // namespace cosmems
