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
  kAuto,     ///< the measured fastest for a band matrix (see Compute)
  kDense,    ///< Eigen's dense LLT: tiny systems
  kBand,     ///< band Cholesky: one beam
  kCholmod,  ///< SuiteSparse CHOLMOD: large or multi-beam systems
};

/// One interface over the three factorisations, so integrators and analyses choose by
/// measurement, not by type. Compute() once; SolveInPlace() allocates nothing.
class SpdSolver {
 public:
  Status Compute(const SymmetricBandMatrix& a, SpdSolverKind kind = SpdSolverKind::kAuto) {
    // kAuto is the band factorisation at every size: per Newmark step it beat dense LLT from
    // one element on (61 vs 77 ns planar) and CHOLMOD at every size measured up to 500
    // elements (18 vs 37 us planar, 55 vs 84 us spatial; bench/linear_step_bench). Dense and
    // CHOLMOD stay available by name; CHOLMOD is for systems whose sparsity is not a band.
    kind_ = kind == SpdSolverKind::kAuto ? SpdSolverKind::kBand : kind;
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
