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
  kAuto,     ///< chosen by size (see SpdSolver::Choose)
  kDense,    ///< Eigen's dense LLT: tiny systems
  kBand,     ///< band Cholesky: one beam
  kCholmod,  ///< SuiteSparse CHOLMOD: large or multi-beam systems
};

/// One interface over the three factorisations, so integrators and analyses choose by
/// measurement, not by type. Compute() once; SolveInPlace() allocates nothing.
class SpdSolver {
 public:
  /// Systems up to this size solve faster densely; beyond it the band wins (bench/
  /// linear_solvers_bench, see the README's table).
  static constexpr int kDenseLimit = 12;
  /// From this size on CHOLMOD's supernodal factor beats the band for a single beam.
  static constexpr int kCholmodFrom = 1 << 30;

  static SpdSolverKind Choose(int size) {
    if (size <= kDenseLimit) return SpdSolverKind::kDense;
    if (size >= kCholmodFrom) return SpdSolverKind::kCholmod;
    return SpdSolverKind::kBand;
  }

  Status Compute(const SymmetricBandMatrix& a, SpdSolverKind kind = SpdSolverKind::kAuto) {
    kind_ = kind == SpdSolverKind::kAuto ? Choose(a.size()) : kind;
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

  /// out = A^-1 (c - A1 x1 - A2 x2), A1 optional; A1 and A2 share A's band. The band solver
  /// forms the right-hand side inside its forward sweep; the others form it first. Allocates
  /// nothing.
  void SolveResidual(const Eigen::VectorXd& c, const SymmetricBandMatrix* a1, const Eigen::VectorXd& x1,
                     const SymmetricBandMatrix& a2, const Eigen::VectorXd& x2, Eigen::VectorXd& out) const {
    if (kind_ == SpdSolverKind::kBand) {
      band_.SolveResidual(c, a1, x1, a2, x2, out);
      return;
    }
    out.setZero();
    a2.MultiplyAdd(x2, out);
    if (a1 != nullptr) a1->MultiplyAdd(x1, out);
    out = c - out;
    SolveInPlace(out);
  }

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
