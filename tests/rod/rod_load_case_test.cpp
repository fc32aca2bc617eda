// RodLoadsFor against statics: the nodal forces it makes must carry the given loads' resultant
// and moment about the root (work equivalence on linear elements implies both), and split a
// point force by the lever rule.
#include "cosmems/rod/rod_load_case.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::kReferenceLength;

// Unequal elements, so the lever rule and the half-lengths are not all alike.
CosseratRod StepBeam() {
  BeamDescription beam = MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                       test::Silicon(), test::ReferenceSection(), 4, 0);
  beam.elements[0].length = 0.1 * kReferenceLength;
  beam.elements[1].length = 0.4 * kReferenceLength;
  return CosseratRod(beam);
}

Eigen::Vector3d Resultant(const RodLoads& loads) { return loads.dead_forces.rowwise().sum(); }

Eigen::Vector3d MomentAboutRoot(const CosseratRod& rod, const RodLoads& loads) {
  Eigen::Vector3d moment = loads.end_moment;
  for (int i = 0; i < rod.NodeCount(); ++i) {
    const Eigen::Vector3d x(rod.NodeX()[i] * rod.units().length, 0.0, 0.0);
    moment += x.cross(loads.dead_forces.col(i));
  }
  return moment;
}

// Sums of a handful of terms of order qL: 1e-14 relative is round-off.
using test::kRoundOff;

TEST(RodLoadCaseTest, DistributedLoadKeepsItsResultantAndMoment) {
  const CosseratRod rod = StepBeam();
  LoadCase loads;
  loads.distributed = Eigen::Vector3d(0.5, -2.0, 1.0);
  const RodLoads nodal = RodLoadsFor(rod, loads);
  const Eigen::Vector3d total = kReferenceLength * loads.distributed;
  EXPECT_TRUE(Resultant(nodal).isApprox(total, kRoundOff));
  const Eigen::Vector3d moment = Eigen::Vector3d(0.5 * kReferenceLength, 0, 0).cross(total);
  EXPECT_TRUE(MomentAboutRoot(rod, nodal).isApprox(moment, kRoundOff));
  // The node between the 0.1 L and 0.4 L elements carries half of each.
  EXPECT_TRUE(nodal.dead_forces.col(1).isApprox(0.25 * total, kRoundOff));
}

TEST(RodLoadCaseTest, PointForceSplitsByTheLeverRule) {
  const CosseratRod rod = StepBeam();
  LoadCase loads;
  const Eigen::Vector3d force(1e-6, -3e-6, 2e-6);
  loads.points.push_back(
      {0.2 * kReferenceLength, force, Eigen::Vector3d::Zero()});  // a quarter into element 1
  const RodLoads nodal = RodLoadsFor(rod, loads);
  EXPECT_TRUE(nodal.dead_forces.col(1).isApprox(0.75 * force, kRoundOff));
  EXPECT_TRUE(nodal.dead_forces.col(2).isApprox(0.25 * force, kRoundOff));
  EXPECT_TRUE(Resultant(nodal).isApprox(force, kRoundOff));
  const Eigen::Vector3d moment = Eigen::Vector3d(0.2 * kReferenceLength, 0, 0).cross(force);
  EXPECT_TRUE(MomentAboutRoot(rod, nodal).isApprox(moment, kRoundOff));
}

TEST(RodLoadCaseTest, TipLoadsGoToTheLastNodeAndItsMoment) {
  const CosseratRod rod = StepBeam();
  LoadCase loads;
  loads.points.push_back(
      {kReferenceLength, Eigen::Vector3d(0, -1e-6, 0), Eigen::Vector3d(0, 0, 2e-12)});
  const RodLoads nodal = RodLoadsFor(rod, loads);
  // The element lengths sum to L within round-off, which is all that leaks to the next node.
  EXPECT_TRUE(nodal.dead_forces.col(4).isApprox(Eigen::Vector3d(0, -1e-6, 0), kRoundOff));
  EXPECT_LT(nodal.dead_forces.leftCols(4).norm(), kRoundOff * 1e-6);
  EXPECT_EQ(nodal.end_moment, Eigen::Vector3d(0, 0, 2e-12));
  EXPECT_TRUE(nodal.follower_force.isZero(0.0));
}

TEST(RodLoadCaseTest, RefusesWhatTheRodCannotCarry) {
  const CosseratRod rod = StepBeam();
  LoadCase inside;
  inside.points.push_back(
      {0.5 * kReferenceLength, Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1e-12)});
  EXPECT_THROW(
      {
        try {
          RodLoadsFor(rod, inside);
        } catch (const std::invalid_argument& e) {
          EXPECT_STREQ(e.what(),
                       "load moment at x = 0.0001 m: a Cosserat rod takes a moment at its last "
                       "node only (x = 0.0002 m)");
          throw;
        }
      },
      std::invalid_argument);
  LoadCase outside;
  outside.points.push_back(
      {1.5 * kReferenceLength, Eigen::Vector3d(0, 1, 0), Eigen::Vector3d::Zero()});
  EXPECT_THROW(RodLoadsFor(rod, outside), std::invalid_argument);
  LoadCase nan;
  nan.distributed.y() = std::nan("");
  EXPECT_THROW(RodLoadsFor(rod, nan), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
