#pragma once

// The tangent oracle of every NonlinearForce: central differences of its energy for the force,
// and of the force for the tangent; and the same force when the band part is not wanted.

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
  // Asked for the rank-one part alone (a Newton iteration on a kept factor), the force gives the
  // same r and rank-one part, to the bit.
  Eigen::VectorXd alone = Eigen::VectorXd::Zero(n);
  ForceTangent rank_one(n, bandwidth);
  rank_one.ClearRankOne();
  ASSERT_TRUE(force.Evaluate(d, alone, rank_one));
  EXPECT_TRUE(alone == r);
  EXPECT_EQ(rank_one.rank_one_scale(), tangent.rank_one_scale());
  if (tangent.rank_one_scale() != 0.0) {
    EXPECT_TRUE(rank_one.rank_one_vector() == tangent.rank_one_vector());
  }
}

/// Expects the tangents of the velocity-dependent part of `force` (EvaluateViscous) at (d, v)
/// within `tolerance` (relative) of central differences of that part: dr/dd with step h in d,
/// dr/dv with step hv in v (dr/dv is what a velocity factor of 1 adds). Also expects the power
/// v^T r it takes to be positive.
inline void ExpectViscousTangentsMatchDifferences(NonlinearForce& force, const Eigen::VectorXd& d,
                                                  const Eigen::VectorXd& v, int bandwidth, double h,
                                                  double hv, double tolerance) {
  const auto n = static_cast<int>(d.size());
  const auto evaluate = [&](const Eigen::VectorXd& dd, const Eigen::VectorXd& vv, double factor,
                            ForceTangent& tangent) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
    tangent.Clear();
    EXPECT_TRUE(force.EvaluateViscous(dd, vv, factor, r, tangent));
    return r;
  };
  ForceTangent at_rest(n, bandwidth), moving(n, bandwidth), scratch(n, bandwidth);
  const Eigen::VectorXd r = evaluate(d, v, 0.0, at_rest);  // dr/dd alone
  evaluate(d, v, 1.0, moving);                             // dr/dd + dr/dv
  EXPECT_GT(v.dot(r), 0.0);
  Eigen::MatrixXd by_d(n, n), by_v(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd plus = d, minus = d;
    plus[j] += h;
    minus[j] -= h;
    by_d.col(j) = (evaluate(plus, v, 0.0, scratch) - evaluate(minus, v, 0.0, scratch)) / (2 * h);
    Eigen::VectorXd faster = v, slower = v;
    faster[j] += hv;
    slower[j] -= hv;
    by_v.col(j) =
        (evaluate(d, faster, 0.0, scratch) - evaluate(d, slower, 0.0, scratch)) / (2 * hv);
  }
  const Eigen::MatrixXd dr_dd = at_rest.ToDense();
  const Eigen::MatrixXd dr_dv = moving.ToDense() - dr_dd;
  EXPECT_LT((by_d - dr_dd).norm(), tolerance * dr_dd.norm());
  EXPECT_LT((by_v - dr_dv).norm(), tolerance * dr_dv.norm());
}

}  // namespace cosmems::test
