// Band storage and the band and CHOLMOD factorisations against Eigen's dense LLT.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <random>

#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/linalg/cholmod_solver.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/linalg/symmetric_band_pair.hpp"

namespace cosmems {
namespace {

// A random symmetric band matrix made diagonally dominant, so positive definite.
SymmetricBandMatrix RandomSpdBand(int n, int bw, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  SymmetricBandMatrix a(n, bw);
  for (int j = 0; j < n; ++j) {
    for (int i = j + 1; i <= std::min(n - 1, j + bw); ++i) a.Add(i, j, u(random));
  }
  for (int j = 0; j < n; ++j) a.Add(j, j, 2.0 * bw + 1.0 + u(random));
  return a;
}

// Products by the fixed-bandwidth kernel (5) and by the general loop (7), overwritten and added.
TEST(SymmetricBandMatrixTest, ProductsAgreeWithDenseForEveryKernel) {
  for (int bw : {0, 3, 5, 7}) {
    const SymmetricBandMatrix a = RandomSpdBand(40, bw, 3);
    const Eigen::MatrixXd dense = a.ToDense();
    const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(40, -1.0, 2.0);
    Eigen::VectorXd y = Eigen::VectorXd::Constant(40, 7.0);  // overwritten, not added to
    a.Multiply(x, y);
    EXPECT_LT((y - dense * x).norm(), 1e-13 * (dense * x).norm()) << bw;
    a.MultiplyAdd(x, y, -0.5);
    EXPECT_LT((y - 0.5 * dense * x).norm(), 1e-13 * (dense * x).norm()) << bw;
  }
}

// The paired products against each matrix's own, to the bit: each lane takes the same operations
// in the same order (the integrators' residuals, hence their iterates, must not move). Fixed
// kernels (3, 5, 11) and the general loop (7, 13), interior and end columns, a matrix smaller
// than its band, and outputs that are the inputs.
TEST(SymmetricBandPairTest, EqualsTheTwoProductsToTheBit) {
  for (int bw : {0, 3, 5, 7, 11, 13}) {
    for (int n : {6, 41}) {
      const SymmetricBandMatrix a = RandomSpdBand(n, std::min(bw, n - 1), 5);
      const SymmetricBandMatrix b = RandomSpdBand(n, std::min(bw, n - 1), 6);
      SymmetricBandPair pair(a, b);
      const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
      const Eigen::VectorXd z = Eigen::VectorXd::LinSpaced(n, 3.0, -0.5).array().exp();
      Eigen::VectorXd ax_expected(n), bz_expected(n);
      a.Multiply(x, ax_expected);
      b.Multiply(z, bz_expected);
      Eigen::VectorXd ax = Eigen::VectorXd::Constant(n, 7.0), bz = ax;  // overwritten
      pair.Multiply(x, z, ax, bz);
      EXPECT_TRUE(ax == ax_expected) << bw << " " << n;
      EXPECT_TRUE(bz == bz_expected) << bw << " " << n;
      Eigen::VectorXd in_out_x = x, in_out_z = z;
      pair.Multiply(in_out_x, in_out_z, in_out_x, in_out_z);
      EXPECT_TRUE(in_out_x == ax_expected) << bw << " " << n;
      EXPECT_TRUE(in_out_z == bz_expected) << bw << " " << n;
    }
  }
  EXPECT_THROW(SymmetricBandPair(RandomSpdBand(8, 3, 1), RandomSpdBand(8, 2, 1)),
               std::invalid_argument);
}

TEST(SymmetricBandMatrixTest, MultiplyAndConversionsAgreeWithDense) {
  const SymmetricBandMatrix a = RandomSpdBand(40, 5, 1);
  const Eigen::MatrixXd dense = a.ToDense();
  EXPECT_EQ((dense - dense.transpose()).norm(), 0.0);
  EXPECT_LT((Eigen::MatrixXd(a.ToSparse()) - dense).norm(), 1e-15);
  const Eigen::VectorXd x = Eigen::VectorXd::LinSpaced(40, -1.0, 2.0);
  EXPECT_LT((a * x - dense * x).norm(), 1e-13 * (dense * x).norm());
  EXPECT_EQ(a(3, 20), 0.0);
  EXPECT_EQ(a(2, 5), a(5, 2));
}

// The largest row sum of |A| against the dense matrix's (an indefinite band, with negative
// entries, for the absolute values), and ProductRoundOff within the ceiling it gives, for smooth
// and for alternating x (where |A| |x| and |A x| differ most).
TEST(SymmetricBandMatrixTest, TheAbsoluteRowSumBoundsTheProductRoundOff) {
  for (int bw : {0, 3, 11}) {
    SymmetricBandMatrix a = RandomSpdBand(30, bw, 4);
    for (int j = 0; j < 30; j += 3) a.Add(j, j, -2.0 * a(j, j));
    const double expected = a.ToDense().cwiseAbs().rowwise().sum().maxCoeff();
    EXPECT_NEAR(a.AbsoluteRowSumMax(), expected, 1e-14 * expected) << bw;
    Eigen::VectorXd work(30);
    const Eigen::VectorXd smooth = Eigen::VectorXd::LinSpaced(30, -1.0, 2.0);
    const Eigen::VectorXd alternating =
        smooth.unaryExpr([](double v) { return std::cos(1e3 * v); });
    for (const Eigen::VectorXd& x : {smooth, alternating}) {
      EXPECT_LE(a.ProductRoundOff(x, work), a.ProductRoundOffFactor() * expected * x.norm()) << bw;
    }
  }
}

class BandSolverTest : public ::testing::TestWithParam<std::tuple<int, int>> {};

// Relative forward error of a well-conditioned system (condition number < 10 by diagonal
// dominance): 1e-13 is a few hundred ulps.
TEST_P(BandSolverTest, SolvesLikeDenseCholesky) {
  const auto [n, bw] = GetParam();
  const SymmetricBandMatrix a = RandomSpdBand(n, bw, 7u + n);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, -3.0);
  const Eigen::VectorXd expected = a.ToDense().llt().solve(b);
  const BandCholesky band(a);
  ASSERT_EQ(band.info(), Status::kOk);
  EXPECT_LT((band.Solve(b) - expected).norm(), 1e-13 * expected.norm());
  CholmodSolver cholmod;
  cholmod.Compute(a.ToSparse());
  ASSERT_EQ(cholmod.info(), Status::kOk);
  EXPECT_LT((cholmod.Solve(b) - expected).norm(), 1e-13 * expected.norm());
}

INSTANTIATE_TEST_SUITE_P(Sizes, BandSolverTest,
                         ::testing::Values(std::make_tuple(1, 0), std::make_tuple(12, 5),
                                           std::make_tuple(60, 11), std::make_tuple(300, 11),
                                           std::make_tuple(8, 11),    // a band past the size
                                           std::make_tuple(40, 7)));  // 7: the general loops

// Two right-hand sides solved together give what one at a time gives.
TEST_P(BandSolverTest, SolvesTwoSystemsTogether) {
  const auto [n, bw] = GetParam();
  const SymmetricBandMatrix a = RandomSpdBand(n, bw, 5u + n);
  const BandCholesky band(a);
  ASSERT_EQ(band.info(), Status::kOk);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, -3.0);
  const Eigen::VectorXd c = Eigen::VectorXd::LinSpaced(n, -2.0, 0.5);
  Eigen::VectorXd x = b, y = c;
  band.SolveInPlace(x, y);
  EXPECT_LT((x - band.Solve(b)).norm(), 1e-14 * x.norm());
  EXPECT_LT((y - band.Solve(c)).norm(), 1e-14 * y.norm());
}

// The selected inverse against the dense inverse, entry by entry within the band: the recurrence
// sums at most b products a row from entries of the same size (condition number < 10), so 1e-13
// of the largest entry is a few hundred ulps.
TEST_P(BandSolverTest, InvertsWithinTheBandLikeTheDenseInverse) {
  const auto [n, bw] = GetParam();
  const SymmetricBandMatrix a = RandomSpdBand(n, bw, 11u + n);
  const Eigen::MatrixXd expected = a.ToDense().inverse();
  const BandCholesky band(a);
  ASSERT_EQ(band.info(), Status::kOk);
  const SymmetricBandMatrix inverse = band.InverseWithinBand();
  ASSERT_EQ(inverse.bandwidth(), bw);
  const double largest = expected.cwiseAbs().maxCoeff();
  for (int j = 0; j < n; ++j) {
    for (int i = j; i <= std::min(n - 1, j + bw); ++i) {
      EXPECT_NEAR(inverse(i, j), expected(i, j), 1e-13 * largest) << i << ", " << j;
    }
  }
}

// The band factored once, the rank-one part renewed on it (what a Newton iteration does when
// the band part of its tangent barely moved), against dense LU of the whole sum.
TEST(BandRankOneCholeskyTest, RenewsTheRankOnePartOnAKeptBandFactor) {
  const SymmetricBandMatrix band = RandomSpdBand(50, 5, 9);
  BandRankOneCholesky solver;
  ASSERT_EQ(solver.ComputeBand(band), Status::kOk);
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(50, 2.0, -1.0);
  for (double shift : {0.0, 1.0, 2.0}) {
    const Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(50, 1.0 + shift, 3.0 - shift);
    const double scale = 0.3 + shift;
    const Eigen::MatrixXd dense = band.ToDense() + scale * u * u.transpose();
    const Eigen::VectorXd exact = dense.lu().solve(b);
    Eigen::VectorXd x = b;
    ASSERT_EQ(solver.SetRankOneAndSolve(scale, u, x), Status::kOk);
    EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm()) << shift;
    x = b;  // the renewed part stays for later solves
    solver.SolveInPlace(x);
    EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm()) << shift;
    ASSERT_EQ(solver.SetRankOne(scale, u), Status::kOk);
    x = b;
    solver.SolveInPlace(x);
    EXPECT_LT((x - exact).norm(), 1e-12 * exact.norm()) << shift;
  }
}

TEST(BandCholeskyTest, ReportsASingularMatrixInsteadOfReturningGarbage) {
  SymmetricBandMatrix a(3, 1);  // the stiffness of a free bar: singular
  a.Add(0, 0, 1);
  a.Add(1, 1, 2);
  a.Add(2, 2, 1);
  a.Add(1, 0, -1);
  a.Add(2, 1, -1);
  EXPECT_EQ(BandCholesky(a).info(), Status::kNotPositiveDefinite);
  CholmodSolver cholmod;
  cholmod.Compute(a.ToSparse());
  EXPECT_NE(cholmod.info(), Status::kOk);
}

}  // namespace
}  // namespace cosmems

namespace cosmems {
namespace {

// The automatic choice follows bench/linear_step_bench: CHOLMOD for spatial frames of at most
// 24 unknowns, the band otherwise.
TEST(SpdSolverTest, AutomaticChoiceFollowsTheMeasuredCrossovers) {
  const auto stiffness = [](int unknowns, int bandwidth) {
    return SymmetricBandMatrix(unknowns, bandwidth);
  };
  EXPECT_EQ(SpdSolver::Choose(stiffness(12, 11)), SpdSolverKind::kCholmod);  // 3-D, 2 elements
  EXPECT_EQ(SpdSolver::Choose(stiffness(24, 11)), SpdSolverKind::kCholmod);  // 3-D, 4 elements
  EXPECT_EQ(SpdSolver::Choose(stiffness(30, 11)), SpdSolverKind::kBand);     // 3-D, 5 elements
  EXPECT_EQ(SpdSolver::Choose(stiffness(6, 5)), SpdSolverKind::kBand);       // 2-D, 2 elements
  EXPECT_EQ(SpdSolver::Choose(stiffness(60, 5)), SpdSolverKind::kBand);      // 2-D, 20 elements
}

}  // namespace
}  // namespace cosmems
