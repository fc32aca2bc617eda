#pragma once

// The tangent oracle of every NonlinearForce: central differences of its energy for the force,
// and of the force for the tangent.

#include <gtest/gtest.h>

#include <Eigen/Core>

#include "cosmems/beam/nonlinear_force.hpp"

namespace cosmems::test {

/// Expects r(d) of `force` within `tolerance` (relative) of the central differences of
/// `energy(d)` with step h, and its tangent within `tolerance` of the central differences of
/// r(d); `bandwidth` is the structure's.
template <typename Energy>
void ExpectForceAndTangentMatchDifferences(NonlinearForce& force, const Eigen::VectorXd& d,
                                           int bandwidth, Energy&& energy, double h,
                                           double tolerance) {
  const auto n = static_cast<int>(d.size());
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  ForceTangent tangent(n, bandwidth);
  tangent.Clear();
  ASSERT_TRUE(force.Evaluate(d, r, tangent));
  const Eigen::MatrixXd dense = tangent.ToDense();
  Eigen::VectorXd fd_force(n);
  Eigen::MatrixXd fd_tangent(n, n);
  ForceTangent scratch(n, bandwidth);
  for (int i = 0; i < n; ++i) {
    Eigen::VectorXd plus = d, minus = d;
    plus[i] += h;
    minus[i] -= h;
    fd_force[i] = (energy(plus) - energy(minus)) / (2 * h);
    Eigen::VectorXd rp = Eigen::VectorXd::Zero(n), rm = Eigen::VectorXd::Zero(n);
    scratch.Clear();
    ASSERT_TRUE(force.Evaluate(plus, rp, scratch));
    scratch.Clear();
    ASSERT_TRUE(force.Evaluate(minus, rm, scratch));
    fd_tangent.col(i) = (rp - rm) / (2 * h);
  }
  EXPECT_LT((fd_force - r).norm(), tolerance * r.norm());
  EXPECT_LT((fd_tangent - dense).norm(), tolerance * dense.norm());
}

}  // namespace cosmems::test
