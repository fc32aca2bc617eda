#include "cosmems/linalg/cholmod_solver.hpp"

#include <Eigen/CholmodSupport>

namespace cosmems {

struct CholmodSolver::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  bool analysed = false;
  bool factorised = false;
};

CholmodSolver::CholmodSolver() : impl_(std::make_unique<Impl>()) {
  // A failed factorisation is reported through info(); a library must not print to stderr.
  impl_->llt.cholmod().print = 0;
}
CholmodSolver::~CholmodSolver() = default;
CholmodSolver::CholmodSolver(CholmodSolver&&) noexcept = default;
CholmodSolver& CholmodSolver::operator=(CholmodSolver&&) noexcept = default;

CholmodSolver& CholmodSolver::AnalyzePattern(const Eigen::SparseMatrix<double>& a) {
  impl_->llt.analyzePattern(a);
  impl_->analysed = impl_->llt.info() == Eigen::Success;
  impl_->factorised = false;
  return *this;
}

CholmodSolver& CholmodSolver::Factorize(const Eigen::SparseMatrix<double>& a) {
  if (!impl_->analysed) AnalyzePattern(a);
  impl_->llt.factorize(a);
  impl_->factorised = impl_->analysed && impl_->llt.info() == Eigen::Success;
  return *this;
}

Status CholmodSolver::info() const {
  return impl_->factorised ? Status::kOk : Status::kNotPositiveDefinite;
}

Eigen::VectorXd CholmodSolver::Solve(const Eigen::VectorXd& b) const {
  return impl_->llt.solve(b);
}

}  // namespace cosmems
