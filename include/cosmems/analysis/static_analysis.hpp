#pragma once

#include <Eigen/Core>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_case.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/cholmod_solver.hpp"

namespace cosmems {

/// Which factorisation a linear solve uses.
enum class LinearSolverKind {
  kBand,     ///< band Cholesky: O(n b^2), the natural choice for one beam
  kCholmod,  ///< SuiteSparse CHOLMOD: for large or multi-beam systems
};

/// A static solution: reduced displacements in the model's internal units (see BeamField for
/// SI quantities along the beam).
struct StaticSolution {
  Status status = Status::kOk;
  Eigen::VectorXd displacement;
};

/// Linear statics K_L u = f under the consistent loads of `loads`.
template <int Dim>
StaticSolution SolveStatic(const BeamModel<Dim>& model, const LoadCase& loads,
                           LinearSolverKind solver = LinearSolverKind::kBand) {
  StaticSolution solution;
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  if (solver == LinearSolverKind::kBand) {
    const BandCholesky cholesky(model.Stiffness());
    solution.status = cholesky.info();
    if (solution.status == Status::kOk) solution.displacement = cholesky.Solve(f);
  } else {
    CholmodSolver cholmod;
    cholmod.Compute(model.Stiffness().ToSparse());
    solution.status = cholmod.info();
    if (solution.status == Status::kOk) solution.displacement = cholmod.Solve(f);
  }
  if (solution.status == Status::kOk && !solution.displacement.allFinite()) {
    solution.status = Status::kNonFinite;
  }
  if (solution.status != Status::kOk) solution.displacement = Eigen::VectorXd::Zero(f.size());
  return solution;
}

}  // namespace cosmems
