#include "cosmems/linalg/cholmod_solver.hpp"

#include <cholmod.h>

#include <Eigen/CholmodSupport>
#include <vector>

namespace cosmems {

// CHOLMOD orders (AMD) and factorises; the per-step solves run here on its packed simplicial
// factor, P A P^T = L L^T. cholmod_solve2 cannot serve them: in SuiteSparse 5 it reshapes its
// workspace during a solve and so allocates again on the next call (tests/time/
// no_allocation_test caught it), and a time step must allocate nothing.
struct CholmodSolver::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  bool factorised = false;
  std::vector<double> work;

  Impl() {
    cholmod_start(&common);
    common.print = 0;  // failures are reported through info(), never printed by a library
    common.supernodal = CHOLMOD_SIMPLICIAL;
    common.final_ll = 1;
  }
  ~Impl() {
    if (factor != nullptr) cholmod_free_factor(&factor, &common);
    cholmod_finish(&common);
  }
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
};

namespace {

// A view of the lower triangle as CHOLMOD's symmetric input; `lower` must outlive the view.
cholmod_sparse LowerView(Eigen::SparseMatrix<double>& lower) {
  cholmod_sparse view = Eigen::viewAsCholmod(lower);
  view.stype = -1;
  return view;
}

}  // namespace

CholmodSolver::CholmodSolver() : impl_(std::make_unique<Impl>()) {}
CholmodSolver::~CholmodSolver() = default;
CholmodSolver::CholmodSolver(CholmodSolver&&) noexcept = default;
CholmodSolver& CholmodSolver::operator=(CholmodSolver&&) noexcept = default;

CholmodSolver& CholmodSolver::AnalyzePattern(const Eigen::SparseMatrix<double>& a) {
  Eigen::SparseMatrix<double> lower = a.triangularView<Eigen::Lower>();
  cholmod_sparse view = LowerView(lower);
  if (impl_->factor != nullptr) cholmod_free_factor(&impl_->factor, &impl_->common);
  impl_->factor = cholmod_analyze(&view, &impl_->common);
  impl_->factorised = false;
  return *this;
}

CholmodSolver& CholmodSolver::Factorize(const Eigen::SparseMatrix<double>& a) {
  if (impl_->factor == nullptr) AnalyzePattern(a);
  impl_->factorised = false;
  if (impl_->factor == nullptr) return *this;
  Eigen::SparseMatrix<double> lower = a.triangularView<Eigen::Lower>();
  cholmod_sparse view = LowerView(lower);
  cholmod_factorize(&view, impl_->factor, &impl_->common);
  cholmod_factor* l = impl_->factor;
  if (impl_->common.status != CHOLMOD_OK || l->minor != l->n) return *this;
  // Packed, monotonic, simplicial LL^T: column j holds its diagonal first, then rows below.
  cholmod_change_factor(CHOLMOD_REAL, 1, 0, 1, 1, l, &impl_->common);
  impl_->factorised = impl_->common.status == CHOLMOD_OK && l->is_ll && !l->is_super;
  impl_->work.assign(l->n, 0.0);
  return *this;
}

Status CholmodSolver::info() const {
  return impl_->factorised ? Status::kOk : Status::kNotPositiveDefinite;
}

void CholmodSolver::SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
  const cholmod_factor* l = impl_->factor;
  const auto n = static_cast<Eigen::Index>(l->n);
  const auto* p = static_cast<const int*>(l->p);
  const auto* row = static_cast<const int*>(l->i);
  const auto* x = static_cast<const double*>(l->x);
  const auto* perm = static_cast<const int*>(l->Perm);
  double* y = impl_->work.data();
  for (Eigen::Index k = 0; k < n; ++k) y[k] = b[perm[k]];
  for (Eigen::Index j = 0; j < n; ++j) {  // L y = P b
    y[j] /= x[p[j]];
    for (int q = p[j] + 1; q < p[j + 1]; ++q) y[row[q]] -= x[q] * y[j];
  }
  for (Eigen::Index j = n - 1; j >= 0; --j) {  // L^T z = y
    double s = y[j];
    for (int q = p[j] + 1; q < p[j + 1]; ++q) s -= x[q] * y[row[q]];
    y[j] = s / x[p[j]];
  }
  for (Eigen::Index k = 0; k < n; ++k) b[perm[k]] = y[k];
}

Eigen::VectorXd CholmodSolver::Solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = b;
  SolveInPlace(x);
  return x;
}

}  // namespace cosmems
