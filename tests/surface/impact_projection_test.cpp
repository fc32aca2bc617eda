// The inelastic impact's projection (ImpactProjection) against the formula written densely in the
// test, x - M^-1 C^T (C M^-1 C^T)^-1 C x, as the held set changes from call to call: points join,
// leave and come back in another order, so each call's columns mix ones solved for earlier sets
// with new ones. The projection is exact linear algebra on a well-conditioned mass (a diagonally
// dominant band): 1e-12 of the motion's norm leaves room for the two orders of summation.
#include "cosmems/surface/impact_projection.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cstdlib>
#include <vector>

namespace cosmems {
namespace {
namespace impact_projection {  // apart from the other surface tests in the same unity build

constexpr int kSize = 14;
constexpr int kPoints = 6;

// Point k's row: its weights over three neighbouring unknowns, as a beam node's motion normal to
// the substrate mixes its displacement and its slopes.
Eigen::VectorXd Row(int k) {
  Eigen::VectorXd row = Eigen::VectorXd::Zero(kSize);
  row.segment(2 * k, 3) << 1.0, 0.3 * (k + 1), -0.2;
  return row;
}

Eigen::VectorXd Projected(const Eigen::MatrixXd& mass, const std::vector<int>& held,
                          const Eigen::VectorXd& x) {
  Eigen::MatrixXd c(held.size(), kSize);
  for (std::size_t i = 0; i < held.size(); ++i) c.row(static_cast<Eigen::Index>(i)) = Row(held[i]);
  const Eigen::MatrixXd columns = mass.ldlt().solve(c.transpose());
  return x - columns * (c * columns).ldlt().solve(c * x);
}

TEST(ImpactProjectionTest, EachHeldSetIsProjectedAsTheDenseFormulaSays) {
  std::srand(5);
  SymmetricBandMatrix band(kSize, 2);
  band.mutable_data().setRandom();
  band.mutable_data().row(0).array() = 9.0;
  const BandCholesky mass(band);
  ImpactProjection projection(kSize, kPoints);
  const auto row = [](int k, Eigen::Ref<Eigen::VectorXd> column) { column += Row(k); };
  const auto along = [](int k, const Eigen::Ref<const Eigen::VectorXd>& x) {
    return Row(k).dot(x);
  };
  for (const std::vector<int>& held :
       std::vector<std::vector<int>>{{1, 4}, {4, 1, 5}, {0, 5}, {5, 4, 1, 0}, {2}, {4, 1, 5}}) {
    Eigen::VectorXd v = Eigen::VectorXd::Random(kSize), a = Eigen::VectorXd::Random(kSize);
    const Eigen::VectorXd v_expected = Projected(band.ToDense(), held, v);
    const Eigen::VectorXd a_expected = Projected(band.ToDense(), held, a);
    projection.Project(mass, held, static_cast<int>(held.size()), row, along, v, a);
    EXPECT_LT((v - v_expected).norm(), 1e-12 * v_expected.norm()) << held.size();
    EXPECT_LT((a - a_expected).norm(), 1e-12 * a_expected.norm()) << held.size();
    for (int k : held) EXPECT_NEAR(along(k, v), 0.0, 1e-12 * v.norm());
  }
}

}  // namespace impact_projection
}  // namespace
}  // namespace cosmems
