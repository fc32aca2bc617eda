// Linear statics of a beam (its one-member netlist, as every front end builds it) against
// closed-form beam solutions. Hermite elements with consistent loads are nodally exact for
// piecewise-prismatic beams, so the tolerance is round-off: 1e-10 relative covers the condition
// number of the stiffness (about 1e5 at 20 elements).
#include <gtest/gtest.h>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/structure/straight_beam.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

constexpr double kRoundOff = 1e-10;
using test::Eiy;
using test::Eiz;
using test::kReferenceLength;

// The reference beam's netlist (node 0 "root" at x = 0, node 1 "tip" at x = L) with its ends
// anchored as given.
StructureDescription BeamNetlist(int elements, int order, Support root, Support tip,
                                 bool planar = false) {
  StraightBeamDesign d;
  d.material = test::Silicon();
  d.section = test::ReferenceSection();
  d.elements = elements;
  d.series_order = order;
  d.planar = planar;
  StructureDescription s = StraightBeam(d);
  s.nodes[0].anchor = AnchorOf(root);
  s.nodes[1].anchor = AnchorOf(tip);
  return s;
}
StructureDescription CantileverNetlist(int elements, int order, bool planar = false) {
  return BeamNetlist(elements, order, Support::kClamped, Support::kFree, planar);
}
StructureDescription BridgeNetlist(int elements, int order) {
  return BeamNetlist(elements, order, Support::kClamped, Support::kClamped);
}

// A force and moment at the point x [m] along the beam: at its tip node, or between its ends.
FrameLoadCase PointAt(double x, Eigen::Vector3d force,
                      Eigen::Vector3d moment = Eigen::Vector3d::Zero()) {
  FrameLoadCase loads;
  if (x == kReferenceLength) {
    loads.points.push_back({1, -1, force, moment});
  } else {
    loads.points.push_back({-1, -1, force, moment, 0, x / kReferenceLength});
  }
  return loads;
}

// The solved beam's motion along it: (u [m], theta [rad]) at x, global axes.
struct NetlistField {
  const FrameModel& model;
  FrameStaticSolution solution;

  FrameModel::Motion At(double x) const {
    FrameModel::Motion m = model.MemberMotion(solution.displacement, 0, x / kReferenceLength);
    m.head<3>() *= model.units().length;
    return m;
  }
};

NetlistField SolveNetlist(const FrameModel& model, const FrameLoadCase& loads,
                          SpdSolverKind solver = SpdSolverKind::kBand) {
  NetlistField field{model, SolveFrameStatic(model, loads, solver)};
  EXPECT_EQ(field.solution.status, Status::kOk);
  return field;
}

TEST(StaticAnalysisTest, OneElementCantileverIsExactUnderATipForce) {
  const double p = -1e-7;
  for (int order : {0, 1}) {
    const FrameModel model(CantileverNetlist(1, order, true));
    const auto tip = SolveNetlist(model, PointAt(kReferenceLength, {0, p, 0})).At(kReferenceLength);
    EXPECT_NEAR(tip[1], p * kReferenceLength * kReferenceLength * kReferenceLength / (3 * Eiz()),
                kRoundOff * std::abs(tip[1]));
    EXPECT_NEAR(tip[5], p * kReferenceLength * kReferenceLength / (2 * Eiz()),
                kRoundOff * std::abs(tip[5]));
  }
}

TEST(StaticAnalysisTest, CantileverUnderTipMomentBendsIntoTheClosedForm) {
  const double m = 3e-12;
  const FrameModel model(CantileverNetlist(1, 0, true));
  const auto tip =
      SolveNetlist(model, PointAt(kReferenceLength, {0, 0, 0}, {0, 0, m})).At(kReferenceLength);
  EXPECT_NEAR(tip[1], m * kReferenceLength * kReferenceLength / (2 * Eiz()),
              kRoundOff * std::abs(tip[1]));
  EXPECT_NEAR(tip[5], m * kReferenceLength / Eiz(), kRoundOff * std::abs(tip[5]));
}

TEST(StaticAnalysisTest, SpatialCantileverAnswersEveryLoadComponent) {
  const Material si = test::Silicon();
  const RectangularSection s = test::ReferenceSection();
  const FrameModel model(CantileverNetlist(5, 1));
  const double f = 1e-6, t = 1e-12, mb = 2e-12;
  const NetlistField field = SolveNetlist(model, PointAt(kReferenceLength, {f, f, f}, {t, mb, 0}));
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
  EXPECT_NEAR(field.solution.axial_force_n, f, kRoundOff * f);
  // The tip node's motion as the solution reports it, the same point.
  EXPECT_TRUE(field.solution.nodes[1].isApprox(tip, 1e-12));
}

TEST(StaticAnalysisTest, BridgeUnderCentreLoadAndUniformLoad) {
  const double p = -1e-5, q = -0.05;
  const FrameModel model(BridgeNetlist(4, 1));
  const double centre =
      SolveNetlist(model, PointAt(kReferenceLength / 2, {0, p, 0})).At(kReferenceLength / 2)[1];
  EXPECT_NEAR(centre, p * kReferenceLength * kReferenceLength * kReferenceLength / (192 * Eiz()),
              kRoundOff * std::abs(centre));
  FrameLoadCase uniform;
  uniform.distributed = {0, q, 0};
  const double sag = SolveNetlist(model, uniform).At(kReferenceLength / 2)[1];
  EXPECT_NEAR(
      sag,
      q * kReferenceLength * kReferenceLength * kReferenceLength * kReferenceLength / (384 * Eiz()),
      kRoundOff * std::abs(sag));
}

// A centre load inside an element (3 elements): the consistent point load keeps the nodes at
// x = L/3, 2L/3 exact on w(x) = P x^2 (3L - 4x) / (48 EI).
TEST(StaticAnalysisTest, PointLoadBetweenNodesKeepsTheNodesExact) {
  const double p = -1e-5;
  const FrameModel model(BridgeNetlist(3, 0));
  const NetlistField field = SolveNetlist(model, PointAt(kReferenceLength / 2, {0, p, 0}));
  const double x = kReferenceLength / 3;
  const double expected = p * x * x * (3 * kReferenceLength - 4 * x) / (48 * Eiz());
  EXPECT_NEAR(field.At(x)[1], expected, kRoundOff * std::abs(expected));
  EXPECT_NEAR(field.At(2 * x)[1], expected, kRoundOff * std::abs(expected));
}

TEST(StaticAnalysisTest, PinnedAndGuidedSupports) {
  const double q = -0.05, p = -1e-6;
  FrameLoadCase uniform;
  uniform.distributed = {0, q, 0};
  const FrameModel pinned(BeamNetlist(6, 1, Support::kPinned, Support::kPinned));
  const double sag = SolveNetlist(pinned, uniform).At(kReferenceLength / 2)[1];
  EXPECT_NEAR(sag, 5 * q * std::pow(kReferenceLength, 4) / (384 * Eiz()),
              kRoundOff * std::abs(sag));

  const FrameModel guided(BeamNetlist(3, 0, Support::kClamped, Support::kGuided, true));
  const FrameModel::Motion end =
      SolveNetlist(guided, PointAt(kReferenceLength, {0, p, 0})).solution.nodes[1];
  EXPECT_NEAR(end[1], p * std::pow(kReferenceLength, 3) / (12 * Eiz()),
              kRoundOff * std::abs(end[1]));
  EXPECT_EQ(end[5], 0.0);
}

// Unit-load method for a two-part cantilever: d = P/EI1 int_0^a (L-x)^2 + P/EI2 int_a^L (L-x)^2,
// the outer half softer and thinner: two collinear members of different material and section.
TEST(StaticAnalysisTest, MultiMaterialCantileverFollowsTheUnitLoadMethod) {
  const double a = kReferenceLength / 2;
  StructureDescription beam;
  beam.series_order = 1;
  beam.nodes.push_back({"root", {0.0, 0.0, 0.0}, AnchorOf(Support::kClamped)});
  beam.nodes.push_back({"joint", {a, 0.0, 0.0}, AnchorOf(Support::kFree)});
  beam.nodes.push_back({"tip", {kReferenceLength, 0.0, 0.0}, AnchorOf(Support::kFree)});
  StructureMember inner;
  inner.from = 0;
  inner.to = 1;
  inner.material = test::Silicon();
  inner.section = test::ReferenceSection();
  inner.elements = 2;
  StructureMember outer = inner;
  outer.from = 1;
  outer.to = 2;
  outer.material.young_modulus = 70e9;
  outer.section.thickness = 1.5e-6;
  beam.members = {inner, outer};
  const double p = -1e-7;
  const double ei1 = Eiz();
  const double ei2 = 70e9 * RectangularSection{20e-6, 1.5e-6}.SecondMomentZ();
  const double expected =
      p / ei1 * (std::pow(kReferenceLength, 3) - std::pow(kReferenceLength - a, 3)) / 3 +
      p / ei2 * std::pow(kReferenceLength - a, 3) / 3;
  const FrameModel model(beam);
  FrameLoadCase tip;
  tip.points.push_back({2, -1, {0, p, 0}, Eigen::Vector3d::Zero()});
  const FrameStaticSolution s = SolveFrameStatic(model, tip);
  ASSERT_EQ(s.status, Status::kOk);
  EXPECT_NEAR(s.nodes[2][1], expected, kRoundOff * std::abs(expected));
}

TEST(StaticAnalysisTest, BendingStressAtTheRootIsPLcOverI) {
  const double p = -1e-7;
  const FrameModel model(CantileverNetlist(20, 1));
  const double stress =
      SolveNetlist(model, PointAt(kReferenceLength, {0, p, 0})).solution.max_stress_pa;
  const double expected =
      std::abs(p) * kReferenceLength * 1e-6 / test::ReferenceSection().SecondMomentZ();
  EXPECT_NEAR(stress, expected, kRoundOff * expected);
}

TEST(StaticAnalysisTest, CholmodAndBandPathsAgree) {
  const FrameModel model(BridgeNetlist(50, 1));
  const FrameLoadCase loads = PointAt(0.3 * kReferenceLength, {1e-6, -1e-5, 2e-6}, {1e-12, 0, 0});
  const Eigen::VectorXd band = SolveFrameStatic(model, loads, SpdSolverKind::kBand).displacement;
  const Eigen::VectorXd cholmod =
      SolveFrameStatic(model, loads, SpdSolverKind::kCholmod).displacement;
  EXPECT_LT((band - cholmod).norm(), kRoundOff * band.norm());
}

TEST(StaticAnalysisTest, UnsupportedBeamIsAStatusNotACrash) {
  const FrameModel model(BeamNetlist(3, 1, Support::kFree, Support::kFree));
  const FrameStaticSolution s = SolveFrameStatic(model, PointAt(kReferenceLength, {0, -1e-7, 0}));
  EXPECT_EQ(s.status, Status::kNotPositiveDefinite);
  EXPECT_TRUE(s.displacement.allFinite());
}

// A planar beam refuses what it cannot carry (an out-of-plane force or moment, a distributed
// load along z), a point off its member, and a non-finite value, each naming the entry.
TEST(StaticAnalysisTest, RejectsLoadsThatCannotActOnTheModel) {
  const FrameModel planar(CantileverNetlist(2, 1, true));
  auto refusal = [&](const FrameLoadCase& loads) {
    try {
      SolveFrameStatic(planar, loads);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(PointAt(kReferenceLength, {0, 0, 1e-6})).rfind("loads.points[0]: a planar", 0),
            0u);
  EXPECT_EQ(
      refusal(PointAt(kReferenceLength, {0, -1e-6, 0}, {1e-12, 0, 0})).rfind("loads.points[0]", 0),
      0u);
  FrameLoadCase across;
  across.distributed = {0, 0, -0.05};
  EXPECT_EQ(refusal(across).rfind("loads.distributed: a planar", 0), 0u);
  FrameLoadCase beyond;
  beyond.points.push_back({-1, -1, {0, -1e-6, 0}, Eigen::Vector3d::Zero(), 0, 2.0});
  EXPECT_EQ(refusal(beyond).rfind("loads.points[0].at = 2", 0), 0u);
  EXPECT_EQ(refusal(PointAt(kReferenceLength, {0, std::nan(""), 0})).rfind("loads.points[0]", 0),
            0u);
}

}  // namespace
}  // namespace cosmems
