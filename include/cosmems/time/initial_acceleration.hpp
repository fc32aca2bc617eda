#pragma once

#include <Eigen/Core>

#include "cosmems/core/status.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/rayleigh_damping.hpp"

namespace cosmems {

/// The acceleration that balances a state: M a0 = g - C v0 - K d0 with C = cM M + cK K, where
/// g is the load at t = 0 less any nonlinear internal force there. One factorisation of M:
/// set-up work, not a step.
inline Status InitialAcceleration(const SymmetricBandMatrix& mass,
                                  const SymmetricBandMatrix& stiffness, RayleighDamping damping,
                                  const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                                  const Eigen::VectorXd& g, Eigen::VectorXd& a0) {
  Eigen::VectorXd product(d0.size());
  stiffness.Multiply(d0 + damping.stiffness * v0, product);
  a0 = g - product;
  mass.Multiply(v0, product);
  a0 -= damping.mass * product;
  SpdSolver mass_solver;
  if (mass_solver.Compute(mass) != Status::kOk) return mass_solver.info();
  mass_solver.SolveInPlace(a0);
  return a0.allFinite() ? Status::kOk : Status::kNonFinite;
}

}  // namespace cosmems
