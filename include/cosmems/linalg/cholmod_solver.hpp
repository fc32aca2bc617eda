#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>

#include "cosmems/core/status.hpp"

namespace cosmems {

/// Sparse Cholesky by SuiteSparse CHOLMOD (simplicial LL^T, AMD ordering) for large or multi-beam
/// systems. CHOLMOD stays private to the compiled library: this interface speaks Eigen only.
///
/// Eigen's idiom: AnalyzePattern() once per sparsity pattern, Factorize() per matrix with that
/// pattern, Solve(), info().
class CholmodSolver {
 public:
  CholmodSolver();
  ~CholmodSolver();
  CholmodSolver(CholmodSolver&&) noexcept;
  CholmodSolver& operator=(CholmodSolver&&) noexcept;
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  /// `a` holds both triangles of a symmetric matrix.
  CholmodSolver& AnalyzePattern(const Eigen::SparseMatrix<double>& a);
  CholmodSolver& Factorize(const Eigen::SparseMatrix<double>& a);
  CholmodSolver& Compute(const Eigen::SparseMatrix<double>& a) {
    return AnalyzePattern(a).Factorize(a);
  }

  Status info() const;
  /// Solves A x = b in place; allocates nothing once Factorize() has succeeded.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const;
  Eigen::VectorXd Solve(const Eigen::VectorXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cosmems
