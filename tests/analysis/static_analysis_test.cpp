// Linear statics against closed-form beam solutions. Hermite elements with consistent loads
// are nodally exact for piecewise-prismatic beams, so the tolerance is round-off: 1e-10
// relative covers the condition number of the stiffness (about 1e5 at 20 elements).
#include <gtest/gtest.h>

#include "test_beams.hpp"

namespace cosmems {
namespace {

constexpr double kRoundOff = 1e-10;
using test::Eiy;
using test::Eiz;
using test::kReferenceLength;

LoadCase PointAt(double x, Eigen::Vector3d force,
                 Eigen::Vector3d moment = Eigen::Vector3d::Zero()) {
  LoadCase loads;
  loads.points.push_back({x, force, moment});
  return loads;
}

template <int Dim>
BeamField<Dim> Solve(const BeamModel<Dim>& model, const LoadCase& loads,
                     LinearSolverKind solver = LinearSolverKind::kBand) {
  const StaticSolution s = SolveStatic(model, loads, solver);
  EXPECT_EQ(s.status, Status::kOk);
  return BeamField<Dim>(model, s.displacement);
}

TEST(StaticAnalysisTest, OneElementCantileverIsExactUnderATipForce) {
  const double p = -1e-7;
  for (int order : {0, 1}) {
    const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                           test::Silicon(), test::ReferenceSection(), 1, order));
    const auto tip = Solve(model, PointAt(kReferenceLength, {0, p, 0})).At(kReferenceLength);
    EXPECT_NEAR(tip[1], p * kReferenceLength * kReferenceLength * kReferenceLength / (3 * Eiz()),
                kRoundOff * std::abs(tip[1]));
    EXPECT_NEAR(tip[5], p * kReferenceLength * kReferenceLength / (2 * Eiz()),
                kRoundOff * std::abs(tip[5]));
  }
}

TEST(StaticAnalysisTest, CantileverUnderTipMomentBendsIntoTheClosedForm) {
  const double m = 3e-12;
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 1, 0));
  const auto tip =
      Solve(model, PointAt(kReferenceLength, {0, 0, 0}, {0, 0, m})).At(kReferenceLength);
  EXPECT_NEAR(tip[1], m * kReferenceLength * kReferenceLength / (2 * Eiz()),
              kRoundOff * std::abs(tip[1]));
  EXPECT_NEAR(tip[5], m * kReferenceLength / Eiz(), kRoundOff * std::abs(tip[5]));
}

TEST(StaticAnalysisTest, SpatialCantileverAnswersEveryLoadComponent) {
  const Material si = test::Silicon();
  const RectangularSection s = test::ReferenceSection();
  const BeamModel<3> model(
      MakeStructure(StructureKind::kCantilever, kReferenceLength, si, s, 5, 1));
  const double f = 1e-6, t = 1e-12, mb = 2e-12;
  const auto field = Solve(model, PointAt(kReferenceLength, {f, f, f}, {t, mb, 0}));
  const auto tip = field.At(kReferenceLength);
  const double ea = si.young_modulus * s.Area();
  const double gj = si.ShearModulus() * s.TorsionConstant();
  EXPECT_NEAR(tip[0], f * kReferenceLength / ea, kRoundOff * std::abs(tip[0]));
  EXPECT_NEAR(tip[1], f * kReferenceLength * kReferenceLength * kReferenceLength / (3 * Eiz()),
              kRoundOff * std::abs(tip[1]));
  // About y: r_y = -duz/dx, and a positive moment about y bends the tip toward -z.
  EXPECT_NEAR(tip[2],
              f * kReferenceLength * kReferenceLength * kReferenceLength / (3 * Eiy()) -
                  mb * kReferenceLength * kReferenceLength / (2 * Eiy()),
              kRoundOff * std::abs(tip[2]));
  EXPECT_NEAR(
      tip[4],
      -f * kReferenceLength * kReferenceLength / (2 * Eiy()) + mb * kReferenceLength / Eiy(),
      kRoundOff * std::abs(tip[4]));
  EXPECT_NEAR(tip[3], t * kReferenceLength / gj, kRoundOff * std::abs(tip[3]));
  EXPECT_NEAR(field.AxialForce(0), f, kRoundOff * f);
}

TEST(StaticAnalysisTest, BridgeUnderCentreLoadAndUniformLoad) {
  const double p = -1e-5, q = -0.05;
  const BeamModel<3> model(MakeStructure(StructureKind::kBridge, kReferenceLength, test::Silicon(),
                                         test::ReferenceSection(), 4, 1));
  const double centre =
      Solve(model, PointAt(kReferenceLength / 2, {0, p, 0})).At(kReferenceLength / 2)[1];
  EXPECT_NEAR(centre, p * kReferenceLength * kReferenceLength * kReferenceLength / (192 * Eiz()),
              kRoundOff * std::abs(centre));
  LoadCase uniform;
  uniform.distributed = {0, q, 0};
  const double sag = Solve(model, uniform).At(kReferenceLength / 2)[1];
  EXPECT_NEAR(
      sag,
      q * kReferenceLength * kReferenceLength * kReferenceLength * kReferenceLength / (384 * Eiz()),
      kRoundOff * std::abs(sag));
}

// A centre load inside an element (3 elements): the consistent point load keeps the nodes at
// x = L/3, 2L/3 exact on w(x) = P x^2 (3L - 4x) / (48 EI).
TEST(StaticAnalysisTest, PointLoadBetweenNodesKeepsTheNodesExact) {
  const double p = -1e-5;
  const BeamModel<2> model(MakeStructure(StructureKind::kBridge, kReferenceLength, test::Silicon(),
                                         test::ReferenceSection(), 3, 0));
  const auto nodes = Solve(model, PointAt(kReferenceLength / 2, {0, p, 0})).AtNodes();
  const double x = kReferenceLength / 3;
  const double expected = p * x * x * (3 * kReferenceLength - 4 * x) / (48 * Eiz());
  EXPECT_NEAR(nodes(1, 1), expected, kRoundOff * std::abs(expected));
  EXPECT_NEAR(nodes(2, 1), expected, kRoundOff * std::abs(expected));
}

TEST(StaticAnalysisTest, PinnedAndGuidedSupports) {
  const double q = -0.05, p = -1e-6;
  BeamDescription pinned =
      UniformBeam(kReferenceLength, test::Silicon(), test::ReferenceSection(), 6, 1);
  pinned.supports.front() = pinned.supports.back() = Support::kPinned;
  LoadCase uniform;
  uniform.distributed = {0, q, 0};
  const double sag = Solve(BeamModel<3>(pinned), uniform).At(kReferenceLength / 2)[1];
  EXPECT_NEAR(sag, 5 * q * std::pow(kReferenceLength, 4) / (384 * Eiz()),
              kRoundOff * std::abs(sag));

  BeamDescription guided =
      UniformBeam(kReferenceLength, test::Silicon(), test::ReferenceSection(), 3, 0);
  guided.supports.front() = Support::kClamped;
  guided.supports.back() = Support::kGuided;
  const auto end =
      Solve(BeamModel<2>(guided), PointAt(kReferenceLength, {0, p, 0})).At(kReferenceLength);
  EXPECT_NEAR(end[1], p * std::pow(kReferenceLength, 3) / (12 * Eiz()),
              kRoundOff * std::abs(end[1]));
  EXPECT_EQ(end[5], 0.0);
}

// Unit-load method for a two-part cantilever: d = P/EI1 int_0^a (L-x)^2 + P/EI2 int_a^L (L-x)^2.
TEST(StaticAnalysisTest, MultiMaterialCantileverFollowsTheUnitLoadMethod) {
  BeamDescription beam =
      UniformBeam(kReferenceLength, test::Silicon(), test::ReferenceSection(), 4, 1);
  for (int e = 2; e < 4; ++e) {
    beam.elements[e].material.young_modulus = 70e9;  // a softer outer half
    beam.elements[e].section.thickness = 1.5e-6;     // and thinner: a stepped, tapered beam
  }
  beam.supports.front() = Support::kClamped;
  const double p = -1e-7;
  const double ei1 = Eiz();
  const double ei2 = 70e9 * RectangularSection{20e-6, 1.5e-6}.SecondMomentZ();
  const double a = kReferenceLength / 2;
  const double expected =
      p / ei1 * (std::pow(kReferenceLength, 3) - std::pow(kReferenceLength - a, 3)) / 3 +
      p / ei2 * std::pow(kReferenceLength - a, 3) / 3;
  const double tip =
      Solve(BeamModel<3>(beam), PointAt(kReferenceLength, {0, p, 0})).At(kReferenceLength)[1];
  EXPECT_NEAR(tip, expected, kRoundOff * std::abs(expected));
}

TEST(StaticAnalysisTest, BendingStressAtTheRootIsPLcOverI) {
  const double p = -1e-7;
  const BeamModel<3> model(MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 1));
  const double stress = Solve(model, PointAt(kReferenceLength, {0, p, 0})).MaxStress();
  const double expected =
      std::abs(p) * kReferenceLength * 1e-6 / test::ReferenceSection().SecondMomentZ();
  EXPECT_NEAR(stress, expected, kRoundOff * expected);
}

TEST(StaticAnalysisTest, CholmodAndBandPathsAgree) {
  const BeamModel<3> model(MakeStructure(StructureKind::kBridge, kReferenceLength, test::Silicon(),
                                         test::ReferenceSection(), 50, 1));
  const LoadCase loads = PointAt(0.3 * kReferenceLength, {1e-6, -1e-5, 2e-6}, {1e-12, 0, 0});
  const Eigen::VectorXd band = SolveStatic(model, loads, LinearSolverKind::kBand).displacement;
  const Eigen::VectorXd cholmod =
      SolveStatic(model, loads, LinearSolverKind::kCholmod).displacement;
  EXPECT_LT((band - cholmod).norm(), kRoundOff * band.norm());
}

TEST(StaticAnalysisTest, UnsupportedBeamIsAStatusNotACrash) {
  const BeamDescription free =
      UniformBeam(kReferenceLength, test::Silicon(), test::ReferenceSection(), 3, 1);
  const BeamModel<3> model(free);
  const StaticSolution s = SolveStatic(model, PointAt(kReferenceLength, {0, -1e-7, 0}));
  EXPECT_EQ(s.status, Status::kNotPositiveDefinite);
  EXPECT_TRUE(s.displacement.allFinite());
}

TEST(StaticAnalysisTest, RejectsLoadsThatCannotActOnTheModel) {
  const BeamModel<2> planar(MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                          test::Silicon(), test::ReferenceSection(), 2, 1));
  EXPECT_THROW(SolveStatic(planar, PointAt(kReferenceLength, {0, 0, 1e-6})), std::invalid_argument);
  EXPECT_THROW(SolveStatic(planar, PointAt(2 * kReferenceLength, {0, -1e-6, 0})),
               std::invalid_argument);
  EXPECT_THROW(SolveStatic(planar, PointAt(kReferenceLength, {0, std::nan(""), 0})),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
