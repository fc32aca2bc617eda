// The cantilever and the bridge as one-member netlists (StraightBeam) on the frame model: the
// beam's oracles on chains. Planar and spatial chains against BeamModel (the same unknowns, band
// and answers to round-off), and against closed forms: a tip-loaded cantilever's cubic along the
// span, a prestressed beam's exact frequencies and second-order deflection, Euler's load less a
// residual compression.
#include <gtest/gtest.h>

#include <cmath>

#include "prestressed_beam_exact.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::kReferenceLength;

StraightBeamDesign ChainDesign(bool bridge, int elements, int order, bool planar,
                               double axial_load = 0.0) {
  StraightBeamDesign d;
  d.bridge = bridge;
  d.length = kReferenceLength;
  d.material = test::Silicon();
  d.section = test::ReferenceSection();
  d.elements = elements;
  d.series_order = order;
  d.planar = planar;
  d.axial_load = axial_load;
  return d;
}

// A force p along y halfway along member 0: a load between nodes (FramePointLoad::member).
FrameLoadCase MidspanForce(double p) {
  FrameLoadCase out;
  FramePointLoad load;
  load.member = 0;
  load.at = 0.5;
  load.force = {0.0, p, 0.0};
  out.points.push_back(load);
  return out;
}

BeamDescription ChainAsBeam(const StraightBeamDesign& d) {
  BeamDescription beam =
      MakeStructure(d.bridge ? StructureKind::kBridge : StructureKind::kCantilever, d.length,
                    d.material, d.section, d.elements, d.series_order);
  beam.axial_load = d.axial_load;
  return beam;
}

ModalOptions ChainModeCount(int count) {
  ModalOptions options;
  options.count = count;
  return options;
}

std::vector<double> ChainFrequencies(const StraightBeamDesign& d, int count) {
  const FrameModalResult result =
      SolveFrameModal(FrameModel(StraightBeam(d)), ChainModeCount(count));
  EXPECT_EQ(result.modal.status, Status::kOk);
  std::vector<double> f;
  for (const Mode& mode : result.modal.modes) f.push_back(mode.frequency_hz);
  return f;
}

template <int Dim>
std::vector<double> BeamFrequencies(const StraightBeamDesign& d, int count) {
  const ModalResult result = SolveModal(BeamModel<Dim>(ChainAsBeam(d)), ChainModeCount(count));
  EXPECT_EQ(result.status, Status::kOk);
  std::vector<double> f;
  for (const Mode& mode : result.modes) f.push_back(mode.frequency_hz);
  return f;
}

// The planar chain numbers u_x, u_y, r_z field by field as the planar beam does: the same
// unknowns, the same band (so the same cost a step), and the same frequencies and kinds to the
// eigensolver's round-off (1e-10: both solve the same pencil, assembled in another order), at
// every series order, cantilever and bridge, with and without a residual force.
TEST(StraightBeamTest, APlanarChainIsThePlanarBeam) {
  for (bool bridge : {false, true}) {
    for (int order : {0, 1, 2}) {
      for (double n : {0.0, 3e-5}) {
        const StraightBeamDesign d = ChainDesign(bridge, 20, order, true, n);
        const FrameModel chain(StraightBeam(d));
        const BeamModel<2> beam(ChainAsBeam(d));
        EXPECT_EQ(chain.FreeDofCount(), beam.FreeDofCount());
        EXPECT_EQ(chain.Stiffness().bandwidth(), beam.Stiffness().bandwidth());
        const std::vector<double> a = ChainFrequencies(d, 6), b = BeamFrequencies<2>(d, 6);
        for (int i = 0; i < 6; ++i) {
          EXPECT_NEAR(a[i], b[i], 1e-10 * b[i])
              << "bridge " << bridge << " order " << order << " N " << n << " mode " << i;
        }
      }
    }
  }
}

// The spatial chain with a residual force is the spatial beam with it (tension stiffens the
// bending in both planes alike; the axial and torsional fields take none).
TEST(StraightBeamTest, APrestressedSpatialChainIsTheSpatialBeam) {
  for (double n : {-2e-5, 1e-4}) {
    const StraightBeamDesign d = ChainDesign(false, 16, 1, false, n);
    EXPECT_EQ(FrameModel(StraightBeam(d)).FreeDofCount(), 16 * 6);
    const std::vector<double> a = ChainFrequencies(d, 8), b = BeamFrequencies<3>(d, 8);
    for (int i = 0; i < 8; ++i) EXPECT_NEAR(a[i], b[i], 1e-10 * b[i]) << "N " << n << " mode " << i;
  }
}

// The twist a probe adds (FrameCouplings::kTwist) numbers the spatial chain's u_y, r_z and r_x
// together: three unknowns a node where the bending alone has two, so the band's half-width
// grows from 3 to 5 (the next node's group lies within it), the unknowns stay six a node, and
// the linear answers do not move (1e-10: the same pencil in another order). A planar chain has
// no twist: its numbering does not change.
TEST(StraightBeamTest, TheProbesTwistWidensTheSpatialChainsBandByOneUnknownANode) {
  const StraightBeamDesign spatial = ChainDesign(false, 16, 1, false);
  const FrameModel bending(StraightBeam(spatial));
  const FrameModel twisting(StraightBeam(spatial), FrameCouplings::kTwist);
  EXPECT_EQ(bending.Stiffness().bandwidth(), 3);
  EXPECT_EQ(twisting.Stiffness().bandwidth(), 5);
  EXPECT_EQ(twisting.FreeDofCount(), bending.FreeDofCount());
  EXPECT_TRUE(twisting.Coupled(static_cast<int>(NodalDof::kUy), static_cast<int>(NodalDof::kRx)));
  EXPECT_FALSE(bending.Coupled(static_cast<int>(NodalDof::kUy), static_cast<int>(NodalDof::kRx)));
  EXPECT_FALSE(twisting.Coupled(static_cast<int>(NodalDof::kUz), static_cast<int>(NodalDof::kRx)));
  const FrameModalResult a = SolveFrameModal(bending, ChainModeCount(8));
  const FrameModalResult b = SolveFrameModal(twisting, ChainModeCount(8));
  ASSERT_EQ(a.modal.status, Status::kOk);
  ASSERT_EQ(b.modal.status, Status::kOk);
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(b.modal.modes[i].frequency_hz, a.modal.modes[i].frequency_hz,
                1e-10 * a.modal.modes[i].frequency_hz);
  }
  const StraightBeamDesign planar = ChainDesign(true, 16, 1, true);
  EXPECT_EQ(FrameModel(StraightBeam(planar), FrameCouplings::kTwist).Stiffness().bandwidth(),
            FrameModel(StraightBeam(planar)).Stiffness().bandwidth());
}

// Against the exact frequencies of EI w'''' - N w'' = rho A w^2 w (the characteristic
// determinant, tests/prestressed_beam_exact.hpp): the error falls as h^4 (the exact mode is no
// power series about the cubic under N), and 40 elements come within 2e-5 (measured on the beam
// 5.7e-6 at the string-like tau = 400, below 1e-7 for |tau| <= 30).
TEST(StraightBeamTest, APrestressedChainConvergesToTheExactFrequencies) {
  struct Case {
    bool bridge;
    double tau;  // N L^2 / EI
  };
  for (const Case c :
       {Case{false, -2.0}, Case{false, 30.0}, Case{true, -30.0}, Case{true, 400.0}}) {
    const double n = c.tau * test::Eiz() / (kReferenceLength * kReferenceLength);
    const std::vector<double> f20 = ChainFrequencies(ChainDesign(c.bridge, 20, 1, true, n), 3);
    const std::vector<double> f40 = ChainFrequencies(ChainDesign(c.bridge, 40, 1, true, n), 3);
    for (int mode = 1; mode <= 3; ++mode) {
      const double exact = std::sqrt(test::ExactPrestressedLambda(c.bridge, c.tau, mode)) /
                           (2 * kPi * kReferenceLength * kReferenceLength) *
                           std::sqrt(test::Eiz() / test::RhoA());
      const double e20 = std::abs(f20[mode - 1] / exact - 1);
      const double e40 = std::abs(f40[mode - 1] / exact - 1);
      EXPECT_LT(e40, 2e-5) << "tau " << c.tau << " mode " << mode;
      EXPECT_NEAR(std::log2(e20 / e40), 4.0, 0.3) << "tau " << c.tau << " mode " << mode;
    }
  }
}

// Second-order theory of a cantilever with a dead axial force N and a tip force P:
// delta = P / (N k) (k L - tanh k L), k^2 = N / EI, and (tan k L - k L) in compression. Hermite
// elements are not nodally exact under N: 40 elements leave 4e-7 (the beam's measured 1.1e-7
// at tau = 50). The reported axial force is the residual one (no axial load is applied).
TEST(StraightBeamTest, ATensionedChainDeflectsAsSecondOrderTheory) {
  const double p = -1e-7;
  for (double tau : {-2.0, 5.0, 50.0}) {
    const double n = tau * test::Eiz() / (kReferenceLength * kReferenceLength);
    const double kl = std::sqrt(std::abs(tau));
    const double exact = tau > 0 ? p * kReferenceLength / (n * kl) * (kl - std::tanh(kl))
                                 : p * kReferenceLength / (-n * kl) * (std::tan(kl) - kl);
    for (bool planar : {true, false}) {
      const FrameModel chain(StraightBeam(ChainDesign(false, 40, 1, planar, n)));
      FrameLoadCase loads;
      loads.points.push_back({1, -1, {0, p, 0}, {0, 0, 0}});
      const FrameStaticSolution s = SolveFrameStatic(chain, loads);
      ASSERT_EQ(s.status, Status::kOk);
      EXPECT_NEAR(s.nodes[1][1], exact, 4e-7 * std::abs(exact)) << "tau " << tau;
      EXPECT_NEAR(s.axial_force_n, n, 1e-12 * std::abs(n)) << "tau " << tau;
    }
  }
}

// A tip force and moment bend a cantilever into cubics, which the elements' Hermite shapes hold
// exactly: MemberMotion anywhere along the span, between nodes too, gives the closed forms
// u_y = P x^2 (3L - x) / (6 EI_z) + M x^2 / (2 EI_z), r_z = du_y/dx, the same across the width
// with I_y and r_y = -du_z/dx, u_x = F x / EA and the twist T x / GJ, to round-off (1e-10 of
// each field's largest value).
TEST(StraightBeamTest, MemberMotionFollowsTheClosedFormsAlongTheSpan) {
  const StraightBeamDesign d = ChainDesign(false, 7, 1, false);
  const FrameModel chain(StraightBeam(d));
  const Eigen::Vector3d force(2e-6, -1e-7, 3e-7), moment(1e-12, 0.0, 4e-12);
  FrameLoadCase loads;
  loads.points.push_back({1, -1, force, moment});
  const FrameStaticSolution s = SolveFrameStatic(chain, loads);
  ASSERT_EQ(s.status, Status::kOk);
  const double l = d.length, e = d.material.young_modulus;
  const double eiz = e * d.section.SecondMomentZ(), eiy = e * d.section.SecondMomentY();
  const double ea = e * d.section.Area();
  const double gj = d.material.ShearModulus() * d.section.TorsionConstant();
  auto exact = [&](double x) {
    FrameModel::Motion m;
    const double py = force.y(), pz = force.z(), mz = moment.z();
    m[0] = force.x() * x / ea;
    m[1] = py * x * x * (3 * l - x) / (6 * eiz) + mz * x * x / (2 * eiz);
    m[2] = pz * x * x * (3 * l - x) / (6 * eiy);
    m[3] = moment.x() * x / gj;
    m[4] = -pz * x * (2 * l - x) / (2 * eiy);
    m[5] = py * x * (2 * l - x) / (2 * eiz) + mz * x / eiz;
    return m;
  };
  const FrameModel::Motion largest = exact(l).cwiseAbs();
  for (double fraction : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    FrameModel::Motion m = chain.MemberMotion(s.displacement, 0, fraction);
    m.head<3>() *= chain.units().length;
    const FrameModel::Motion want = exact(fraction * l);
    for (int k = 0; k < 6; ++k) {
      EXPECT_NEAR(m[k], want[k], 1e-10 * largest[k]) << "s " << fraction << " component " << k;
    }
  }
}

// The residual force stays in K and is not scaled with the loads: a cantilever column under a
// residual compression N0 and a tip thrust P buckles when N0 + lambda P reaches Euler's
// pi^2 EI / (4 L^2), so lambda P = P_E - |N0| (within the 40-element chain's 1e-6 of the
// column's closed form, as without prestress).
TEST(StraightBeamTest, AResidualCompressionLowersTheThrustThatBuckles) {
  const double euler = kPi * kPi * test::Eiz() / (4 * kReferenceLength * kReferenceLength);
  const double n0 = -0.3 * euler;
  const FrameModel chain(StraightBeam(ChainDesign(false, 40, 1, true, n0)));
  FrameLoadCase thrust;
  thrust.points.push_back({1, -1, {-1e-6, 0, 0}, {0, 0, 0}});
  const FrameBucklingResult result = SolveFrameBuckling(chain, thrust);
  ASSERT_EQ(result.status, Status::kOk);
  EXPECT_NEAR(result.critical_load_n, euler + n0, 1e-6 * euler);
}

// A force between nodes (FramePointLoad on a member) loads the element holding it by its
// consistent nodal forces, as the beam's AssembleLoads: a bridge pressed at midspan across seven
// elements (the load inside the fourth) deflects at every node as the closed form
// w = P x^2 (3L - 4x) / (48 EI) for x <= L/2 (Hermite elements are exact at their nodes: 1e-10),
// and a two-element bridge pressed a quarter along has the closed form's reactions,
// R = 27/32 P, 5/32 P and end moments 9/64 P L, 3/64 P L (1e-12: exact at the nodes).
TEST(StraightBeamTest, AForceBetweenNodesLoadsTheElementHoldingIt) {
  const double p = -2e-6;
  const double l = kReferenceLength;
  const FrameLoadCase midspan = MidspanForce(p);

  const FrameModel bridge(StraightBeam(ChainDesign(true, 7, 1, false)));
  const FrameStaticSolution s = SolveFrameStatic(bridge, midspan);
  ASSERT_EQ(s.status, Status::kOk);
  const double largest = p * l * l * l / (192 * test::Eiz());
  for (int k = 0; k <= 3; ++k) {
    const double x = k * l / 7;
    const double want = p * x * x * (3 * l - 4 * x) / (48 * test::Eiz());
    const double got = bridge.MemberMotion(s.displacement, 0, k / 7.0)[1] * bridge.units().length;
    EXPECT_NEAR(got, want, 1e-10 * std::abs(largest)) << "node " << k;
  }

  // Two elements, the force a quarter along the span, inside the first: the reactions come from
  // the first element's end forces less its share of the load, and from the second's.
  FrameLoadCase quarter = midspan;
  quarter.points[0].at = 0.25;
  const FrameModel two(StraightBeam(ChainDesign(true, 2, 1, false)));
  const FrameStaticSolution r = SolveFrameStatic(two, quarter);
  ASSERT_EQ(r.status, Status::kOk);
  ASSERT_EQ(r.reactions.size(), 2u);
  const double pl = std::abs(p) * l;
  EXPECT_NEAR(r.reactions[0].force.y(), -27.0 / 32 * p, 1e-12 * std::abs(p));
  EXPECT_NEAR(r.reactions[1].force.y(), -5.0 / 32 * p, 1e-12 * std::abs(p));
  EXPECT_NEAR(std::abs(r.reactions[0].moment.z()), 9.0 / 64 * pl, 1e-12 * pl);
  EXPECT_NEAR(std::abs(r.reactions[1].moment.z()), 3.0 / 64 * pl, 1e-12 * pl);

  FramePointLoad outside = midspan.points[0];
  outside.at = 1.5;
  EXPECT_THROW(AssembleFrameLoads(bridge, {{outside}, Eigen::Vector3d::Zero()}),
               std::invalid_argument);
}

// Euler buckling of the member itself (SolveMemberBuckling, a beam scene's buckling): a
// cantilever's pi^2 EI / (4 L^2) and a bridge's 4 pi^2 EI / L^2 whatever residual force the
// member holds (the total thrust it carries), equal to the beam's SolveBuckling to round-off
// (1e-9: two eigen-solves of the same pencil in different orders) and to the closed form within
// the 40-element chain's 1e-6.
TEST(StraightBeamTest, AMemberBucklesAtEulersLoadWhateverItsResidualForce) {
  for (bool bridge : {false, true}) {
    const double euler =
        (bridge ? 4.0 : 0.25) * kPi * kPi * test::Eiz() / (kReferenceLength * kReferenceLength);
    for (double residual : {0.0, -0.3 * euler, 2.0 * euler}) {
      const StraightBeamDesign d = ChainDesign(bridge, 40, 1, true, residual);
      const FrameBucklingResult chain = SolveMemberBuckling(FrameModel(StraightBeam(d)), 0);
      ASSERT_EQ(chain.status, Status::kOk);
      EXPECT_NEAR(chain.critical_load_n, euler, 1e-6 * euler) << bridge << " " << residual;
      const BucklingResult beam = SolveBuckling(BeamModel<2>(ChainAsBeam(d)));
      ASSERT_EQ(beam.status, Status::kOk);
      EXPECT_NEAR(chain.critical_load_n, beam.modes[0].critical_load_n, 1e-9 * euler);
      EXPECT_DOUBLE_EQ(chain.load_factor, chain.critical_load_n);
    }
  }
}

// The largest stress comes from the elements' end forces, which carry each element's share of
// the distributed load: a bridge under a uniform load q has its largest moment q L^2 / 12 at the
// clamps whatever its mesh (the Hermite element's end forces are exact for a uniform load), so
// its largest stress is q L^2 / 12 * (t/2) / I, and its clamps hold q L / 2 each (1e-10: the
// solve's round-off on four elements).
TEST(StraightBeamTest, ALoadedBridgeHasTheClosedFormStressAtItsClamps) {
  const double q = -0.5;  // N/m, toward the substrate
  const double l = kReferenceLength;
  for (int elements : {4, 9}) {
    const FrameModel bridge(StraightBeam(ChainDesign(true, elements, 1, true)));
    FrameLoadCase uniform;
    uniform.distributed = {0.0, q, 0.0};
    const FrameStaticSolution s = SolveFrameStatic(bridge, uniform);
    ASSERT_EQ(s.status, Status::kOk);
    const RectangularSection section = test::ReferenceSection();
    const double stress =
        std::abs(q) * l * l / 12.0 * (0.5 * section.thickness) / section.SecondMomentZ();
    EXPECT_NEAR(s.max_stress_pa, stress, 1e-10 * stress) << elements;
    for (const FrameReaction& r : s.reactions) {
      EXPECT_NEAR(r.force.y(), -0.5 * q * l, 1e-10 * std::abs(q) * l) << elements;
    }
  }
}

// A point along a member as a transient records it (FrameMotionComponent): its weights read the
// member's interpolation, so on the static state of a bridge pressed at midspan across eight
// elements they give MemberMotion's u_y and the closed form P L^3 / (192 EI) at the node there
// (1e-12 and 1e-10: round-off of a weighted sum, and of the solve), and a quarter along, inside an
// element, MemberMotion's u_y to round-off; a member or a fraction the structure lacks throws.
TEST(StraightBeamTest, AMemberPointIsRecordedAsTheMemberMoves) {
  const double p = -2e-6;
  const double l = kReferenceLength;
  const FrameLoadCase midspan = MidspanForce(p);
  for (bool planar : {false, true}) {
    const FrameModel bridge(StraightBeam(ChainDesign(true, 8, 1, planar)));
    const FrameStaticSolution s = SolveFrameStatic(bridge, midspan);
    ASSERT_EQ(s.status, Status::kOk);
    const double largest = p * l * l * l / (192 * test::Eiz());
    for (double at : {0.5, 0.3}) {
      const OutputPoint uy = FrameMotionComponent(bridge, {-1, -1, 0, at}, 1);
      const double want = bridge.MemberMotion(s.displacement, 0, at)[1] * bridge.units().length;
      EXPECT_NEAR(uy.Evaluate(s.displacement), want, 1e-12 * std::abs(largest)) << at;
      if (at == 0.5) {
        EXPECT_NEAR(want, largest, 1e-10 * std::abs(largest));
      }
    }
    EXPECT_THROW(FrameMotionComponent(bridge, {-1, -1, 1, 0.5}, 1), std::invalid_argument);
    EXPECT_THROW(FrameMotionComponent(bridge, {-1, -1, 0, 1.5}, 1), std::invalid_argument);
  }
}

// A planar description out of its plane is refused naming model.dimension.
TEST(StraightBeamTest, APlanarStructureOutOfItsPlaneIsRefused) {
  StructureDescription s = StraightBeam(ChainDesign(false, 4, 1, true));
  s.nodes[1].position.z() = 1e-6;
  try {
    FrameModel model(s);
    FAIL() << "accepted";
  } catch (const FieldError& e) {
    EXPECT_NE(std::string(e.what()).find("model.dimension"), std::string::npos) << e.what();
  }
  StructureDescription tilted = StraightBeam(ChainDesign(false, 4, 1, true));
  tilted.members[0].thickness_direction = {0.0, 1.0, 1.0};
  EXPECT_THROW(FrameModel{tilted}, FieldError);
}

}  // namespace
}  // namespace cosmems
