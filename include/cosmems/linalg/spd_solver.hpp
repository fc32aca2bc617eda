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
  /// The measured fastest per Newmark step (bench/linear_step_bench, README): the band
  /// factorisation, except for bands wider than 5 of at most 24 unknowns. A beam numbered field
  /// by field (BeamModel's default) has a band of 3 and the band won at every size (3-D,
  /// 2 elements: 116 ns against CHOLMOD's 145). Numbered node by node, a spatial frame has a
  /// band of 11 that is mostly zeros, which CHOLMOD's ordering skips: there it won up to 4
  /// elements (182 vs 274 ns) and lost from 5 on (571 vs 509 ns). Dense LLT was slower at every
  /// size (planar, 1 element: 76 vs 53 ns).
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
