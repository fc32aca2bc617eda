#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/band_ldlt.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// Solves (B + s u u^T) x = b for a symmetric band B by Sherman-Morrison (B definite, or B with
/// one negative eigenvalue that a positive s u u^T lifts, see ComputeWithIndefiniteBand):
/// x = B^-1 b - w s (u^T B^-1 b) / (1 + s u^T w), w = B^-1 u. One band factorisation and one
/// extra back-solve per Compute(), one back-solve and two dot products per solve, so a
/// stretching beam keeps the cost of a band.
///
/// The two parts can also be set apart: ComputeBand() factors B alone, SetRankOne() then only
/// solves for w, so a Newton iteration whose band part barely moved keeps B's factor and pays a
/// back-solve for a fresh rank-one part (SetRankOneAndSolve() does that solve together with the
/// system's). Nothing allocates once sized for a given n and bandwidth.
class BandRankOneCholesky {
 public:
  Status Compute(const SymmetricBandMatrix& band, double scale, const Eigen::VectorXd& u) {
    if (ComputeBand(band) == Status::kNotPositiveDefinite) {
      return ComputeWithIndefiniteBand(band, scale, u);
    }
    if (status_ != Status::kOk) return status_;
    return SetRankOne(scale, u);
  }

  /// Factors B and clears the rank-one part.
  Status ComputeBand(const SymmetricBandMatrix& band) {
    indefinite_ = false;
    band_.Compute(band);
    scale_ = 0.0;
    return status_ = band_.info();
  }

  /// B + s u u^T where ComputeBand() found B not definite. A positive rank-one part can make the
  /// sum definite where B is not: a bridge that mid-plane stretching holds beyond the point where
  /// its bending stiffness alone would give way (pressed past the linear pull-in travel, say). B
  /// then has one negative eigenvalue, and by the matrix determinant lemma
  /// det(B + s u u^T) = det(B) (1 + s u^T B^-1 u): the sum, whose other eigenvalues stay above
  /// B's positive ones, is definite exactly when that factor is negative. B is factored by
  /// BandLdlt, which counts the negative eigenvalues; SetRankOne() does not apply to it.
  Status ComputeWithIndefiniteBand(const SymmetricBandMatrix& band, double scale,
                                   const Eigen::VectorXd& u) {
    if (!(scale > 0.0)) return status_ = Status::kNotPositiveDefinite;
    if (ldlt_.Compute(band) != Status::kOk) return status_ = ldlt_.info();
    if (ldlt_.negative_pivots() != 1) return status_ = Status::kNotPositiveDefinite;
    indefinite_ = true;
    scale_ = scale;
    w_ = u;
    ldlt_.SolveInPlace(w_);
    return status_ = Finish(u);
  }

  /// Replaces the rank-one part of the factored B + s u u^T, keeping B's factor.
  Status SetRankOne(double scale, const Eigen::VectorXd& u) {
    if (band_.info() != Status::kOk) return status_ = band_.info();
    scale_ = scale;
    if (scale == 0.0) return status_ = Status::kOk;
    w_ = u;
    band_.SolveInPlace(w_);
    return status_ = Finish(u);
  }

  /// SetRankOne(scale, u) followed by SolveInPlace(b), the two back-solves made together. On
  /// failure b is left half-solved and info() says why.
  Status SetRankOneAndSolve(double scale, const Eigen::VectorXd& u, Eigen::Ref<Eigen::VectorXd> b) {
    if (band_.info() != Status::kOk) return status_ = band_.info();
    scale_ = scale;
    if (scale == 0.0) {
      band_.SolveInPlace(b);
      return status_ = Status::kOk;
    }
    w_ = u;
    band_.SolveInPlace(w_, b);
    if ((status_ = Finish(u)) == Status::kOk) b -= (scale_ * u_.dot(b) / denominator_) * w_;
    return status_;
  }

  Status info() const { return status_; }

  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    if (indefinite_) {
      ldlt_.SolveInPlace(b);
    } else {
      band_.SolveInPlace(b);
    }
    if (scale_ != 0.0) b -= (scale_ * u_.dot(b) / denominator_) * w_;
  }

 private:
  // With w = B^-1 u solved: the denominator, and whether B + s u u^T is definite: when
  // 1 + s u^T B^-1 u > 0 for a definite B, < 0 for a B with one negative eigenvalue.
  Status Finish(const Eigen::VectorXd& u) {
    denominator_ = 1.0 + scale_ * u.dot(w_);
    u_ = u;
    if (!std::isfinite(denominator_)) return Status::kNonFinite;
    const bool definite = indefinite_ ? denominator_ < 0.0 : denominator_ > 0.0;
    return definite ? Status::kOk : Status::kNotPositiveDefinite;
  }

  BandCholesky band_;
  BandLdlt ldlt_;
  bool indefinite_ = false;  // the last Compute() factored B by ldlt_
  Eigen::VectorXd u_, w_;
  double scale_ = 0.0;
  double denominator_ = 1.0;
  Status status_ = Status::kNotPositiveDefinite;
};

}  // namespace cosmems
