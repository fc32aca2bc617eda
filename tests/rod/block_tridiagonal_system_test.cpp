// The rod's block-tridiagonal factorisation against a dense solver, with supports and an
// unsymmetric last block, and its report of an unsupported structure.
#include "cosmems/rod/block_tridiagonal_system.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "cosmems/rod/cosserat_rod.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

TEST(BlockTridiagonalSystemTest, SolvesLikeADenseSolverWithSupportsAndAnUnsymmetricEnd) {
  const int nodes = 7;
  std::vector<std::uint8_t> fixed(nodes, 0);
  fixed[0] = 0x3f;  // a clamp
  fixed[3] = 0x07;  // translations held mid-span
  BlockTridiagonalSystem system(fixed);
  std::mt19937 rng(46);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int i = 0; i < nodes; ++i) {
    BlockTridiagonalSystem::Block a;
    for (int k = 0; k < 36; ++k) a.data()[k] = uniform(rng);
    system.Diagonal(i) = a * a.transpose() + 12.0 * BlockTridiagonalSystem::Block::Identity();
    if (i + 1 < nodes) {
      for (int k = 0; k < 36; ++k) system.Lower(i).data()[k] = uniform(rng);
    }
  }
  for (int k = 0; k < 36; ++k) system.LastUnsymmetric().data()[k] = 2.0 * uniform(rng);
  Eigen::MatrixXd dense = system.ToDense();
  Eigen::VectorXd b = Eigen::VectorXd::Random(6 * nodes);
  // The reduced system: supported rows and columns removed.
  std::vector<int> free;
  for (int i = 0; i < nodes; ++i) {
    for (int k = 0; k < 6; ++k) {
      if (!(fixed[i] & (1u << k))) free.push_back(6 * i + k);
    }
  }
  const int n = static_cast<int>(free.size());
  Eigen::MatrixXd reduced(n, n);
  Eigen::VectorXd rhs(n);
  for (int i = 0; i < n; ++i) {
    rhs[i] = b[free[i]];
    for (int j = 0; j < n; ++j) reduced(i, j) = dense(free[i], free[j]);
  }
  const Eigen::VectorXd expected = reduced.partialPivLu().solve(rhs);
  ASSERT_EQ(system.Factorize(), Status::kOk);
  system.SolveInPlace(b);
  for (int i = 0; i < n; ++i) EXPECT_NEAR(b[free[i]], expected[i], 1e-12 * expected.norm());
  for (int k = 0; k < 6; ++k) EXPECT_EQ(b[k], 0.0);
}

TEST(BlockTridiagonalSystemTest, ReportsAStructureWithoutSupports) {
  CosseratRod rod(MakeStructure(StructureKind::kCantilever, test::kReferenceLength, test::Silicon(),
                                test::ReferenceSection(), 10, 0));
  BeamDescription free_rod = rod.description();
  free_rod.supports.front() = Support::kFree;
  const CosseratRod unsupported(free_rod);
  BlockTridiagonalSystem system = unsupported.MakeSystem();
  CosseratRod::ElementKinematics kinematics = unsupported.MakeKinematics();
  Eigen::VectorXd r(unsupported.DofCount());
  unsupported.InternalForces(unsupported.UndeformedState(), r, kinematics);
  unsupported.InternalTangent(kinematics, system);
  EXPECT_EQ(system.Factorize(), Status::kNotPositiveDefinite);
}

}  // namespace
}  // namespace cosmems
