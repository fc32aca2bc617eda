// BandLdlt against dense Eigen: the solution of an indefinite band system and its inertia
// against the eigenvalues. Random well-conditioned matrices: 1e-10 relative leaves a wide margin
// over the ~1e-14 round-off of a 40-unknown solve.
#include "cosmems/linalg/band_ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cstdlib>

#include "cosmems/linalg/band_rank_one_cholesky.hpp"

namespace cosmems {
namespace {

// A diagonally dominant band matrix shifted so that `negative` eigenvalues fall below zero.
SymmetricBandMatrix Shifted(int n, int bandwidth, int negative) {
  std::srand(11);
  SymmetricBandMatrix a(n, bandwidth);
  a.mutable_data().setRandom();
  a.mutable_data().row(0).array() = 4.0 * bandwidth + 1.0;
  Eigen::VectorXd eigenvalues =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a.ToDense()).eigenvalues();  // ascending
  if (negative > 0) {
    const double shift = 0.5 * (eigenvalues[negative - 1] + eigenvalues[negative]);
    a.mutable_data().row(0).array() -= shift;
  }
  return a;
}

TEST(BandLdltTest, SolvesIndefiniteSystemsAndCountsTheirNegativeEigenvalues) {
  for (int negative : {0, 1, 3}) {
    for (int bandwidth : {1, 3, 5}) {
      const SymmetricBandMatrix a = Shifted(40, bandwidth, negative);
      BandLdlt ldlt;
      ASSERT_EQ(ldlt.Compute(a), Status::kOk);
      EXPECT_EQ(ldlt.negative_pivots(), negative);
      const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(40, -1.0, 2.0);
      Eigen::VectorXd x = b;
      ldlt.SolveInPlace(x);
      const Eigen::VectorXd exact = a.ToDense().lu().solve(b);
      EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm()) << negative << " " << bandwidth;
    }
  }
}

TEST(BandLdltTest, ReportsASingularMatrix) {
  SymmetricBandMatrix a(3, 1);
  a.mutable_data() << 1.0, 1.0, 1.0, 1.0, 1.0, 0.0;  // [[1,1,0],[1,1,1],[0,1,1]]: D_1 = 0
  BandLdlt ldlt;
  EXPECT_EQ(ldlt.Compute(a), Status::kNotPositiveDefinite);
}

// A band with one negative eigenvalue plus a positive rank-one part: definite or not as the
// dense eigenvalues say, and solved as dense LU does when it is.
TEST(BandLdltTest, RankOneSolverTakesABandThatOnlyTheRankOnePartMakesDefinite) {
  const SymmetricBandMatrix band = Shifted(40, 3, 1);
  const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(40, 1.0, 3.0);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(40, 2.0, -1.0);
  for (double scale : {1e-4, 1.0, 100.0}) {
    const Eigen::MatrixXd dense = band.ToDense() + scale * u * u.transpose();
    const double lowest =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(dense).eigenvalues().minCoeff();
    BandRankOneCholesky solver;
    const Status status = solver.Compute(band, scale, u);
    ASSERT_EQ(status == Status::kOk, lowest > 0.0) << scale;
    if (status != Status::kOk) continue;
    Eigen::VectorXd x = b;
    solver.SolveInPlace(x);
    const Eigen::VectorXd exact = dense.lu().solve(b);
    EXPECT_LT((x - exact).norm(), 1e-10 * exact.norm()) << scale;
  }
}

}  // namespace
}  // namespace cosmems
