#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/cholmod_solver.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// Which factorisation solves a symmetric positive definite system.
enum class SpdSolverKind {
  kAuto,     ///< the measured fastest for the matrix (see SpdSolver::Choose)
  kDense,    ///< Eigen's dense LLT: tiny systems
  kBand,     ///< band Cholesky: one beam
  kCholmod,  ///< SuiteSparse CHOLMOD: large or multi-beam systems
};

/// One interface over the three factorisations, so integrators and analyses choose by
/// measurement, not by type. Compute() once; SolveInPlace() allocates nothing.
class SpdSolver {
 public:
  /// The fastest per Newmark step as measured: the band factorisation, except for bands wider
  /// than 5 of at most 24 unknowns, that is small spatial frames numbered node by node, whose band
  /// of 11 is mostly zeros that CHOLMOD's ordering skips. A beam numbered field by field
  /// (BeamModel's default) has a band of 3, and there the band wins at every size; dense LLT
  /// never wins. The figures: doc/speed.md, "Kernel choices".
  static SpdSolverKind Choose(const SymmetricBandMatrix& a) {
    return a.bandwidth() > 5 && a.size() <= 24 ? SpdSolverKind::kCholmod : SpdSolverKind::kBand;
  }

  Status Compute(const SymmetricBandMatrix& a, SpdSolverKind kind = SpdSolverKind::kAuto) {
    kind_ = kind == SpdSolverKind::kAuto ? Choose(a) : kind;
    switch (kind_) {
      case SpdSolverKind::kDense:
        dense_.compute(a.ToDense());
        status_ = dense_.info() == Eigen::Success ? Status::kOk : Status::kNotPositiveDefinite;
        break;
      case SpdSolverKind::kCholmod:
        cholmod_.Compute(a.ToSparse());
        status_ = cholmod_.info();
        break;
      default:
        band_.Compute(a);
        status_ = band_.info();
        break;
    }
    return status_;
  }

  Status info() const { return status_; }
  SpdSolverKind kind() const { return kind_; }
  /// The band factor, for solves that make their right side row by row (BandCholesky::SolveRows);
  /// null for the other kinds.
  const BandCholesky* band() const { return kind_ == SpdSolverKind::kBand ? &band_ : nullptr; }

  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    switch (kind_) {
      case SpdSolverKind::kDense:
        dense_.solveInPlace(b);
        break;
      case SpdSolverKind::kCholmod:
        cholmod_.SolveInPlace(b);
        break;
      default:
        band_.SolveInPlace(b);
        break;
    }
  }

 private:
  SpdSolverKind kind_ = SpdSolverKind::kBand;
  Status status_ = Status::kNotPositiveDefinite;
  Eigen::LLT<Eigen::MatrixXd> dense_;
  BandCholesky band_;
  CholmodSolver cholmod_;
};

}  // namespace cosmems
