// Stiction under any structure (FrameSubstrateContact with adhesion), released from lying on the
// substrate as the release analysis does: a cantilever member inside a frame against the
// validated beam (SubstrateContact) and the closed forms of its shapes, and a plate on four
// springs against the plate's stiction criterion, its springs' stored energy against the
// adhesion of its face; a finely meshed device stuck under the probe keeps its haptic steps.
#include <gtest/gtest.h>

#include <cmath>

#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/structure/folded_flexure.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "structure/test_frames.hpp"
#include "surface/plate_on_four_beams.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {
namespace frame_stiction {  // apart from the beam's helpers in the same unity build

constexpr double kGamma = 0.02;  // J/m^2
constexpr double kCantileverGap = 2e-6;

ContactOptions Adhesion(double gap, double gamma) {
  ContactOptions options;
  options.gap = gap;
  options.stiction = true;
  options.adhesion_energy = gamma;
  return options;
}

// Every site stuck, pressed onto the plane, the statics solved: what the adhesion holds.
Eigen::VectorXd ReleaseDevice(const FrameModel& model, FrameSubstrateContact& contact) {
  contact.StickAll();
  NonlinearStaticOptions options;
  options.start = contact.PressedDisplacement();
  options.newton.max_settles = 10000;
  NonlinearStaticSolve solve(model.Stiffness(), contact, options, nullptr);
  const NonlinearStaticSolution solution = solve.Solve(Eigen::VectorXd::Zero(model.FreeDofCount()));
  EXPECT_EQ(solution.status, Status::kOk);
  return solution.displacement;
}

// The same cantilever as a member between a clamped node and a free one, in the 3-D frame.
StructureDescription CantileverFrame(double length, int elements) {
  StructureDescription s;
  const int clamp = test::AddNode(s, "clamp", Eigen::Vector3d::Zero(), Support::kClamped);
  const int tip = test::AddNode(s, "tip", Eigen::Vector3d(length, 0.0, 0.0));
  s.members.push_back(
      {clamp, tip, test::Silicon(), test::ReferenceSection(), elements, Eigen::Vector3d::UnitY()});
  return s;
}

ContactSummary ReleaseBeam(double length, int elements) {
  const BeamModel<2> model = test::PlanarCantilever(length, elements);
  SubstrateContact<2> contact(model, Adhesion(kCantileverGap, kGamma));
  contact.StickAll();
  NonlinearStaticOptions options;
  options.start = contact.PressedDisplacement();
  EXPECT_EQ(SolveNonlinearStatic(model, contact, LoadCase{}, options).status, Status::kOk);
  return contact.Summary();
}

// The closed forms of the cantilever on its substrate (E t^3 g^2 over Gamma): it touches by its
// tip from the arc-shaped detachment length (3 E t^3 g^2 / 8 Gamma)^(1/4) on (de Boer &
// Michalske), and lies along a length past the S-shaped free span (3 E t^3 g^2 / 2 Gamma)^(1/4)
// (Mastrangelo & Hsu): 100 and 142 um here.
double Stiffness() {
  return test::Silicon().young_modulus * std::pow(test::ReferenceSection().thickness, 3) *
         kCantileverGap * kCantileverGap;
}
double ArcLength() { return std::pow(3.0 * Stiffness() / (8.0 * kGamma), 0.25); }
double StuckSpan() { return std::pow(3.0 * Stiffness() / (2.0 * kGamma), 0.25); }

// Free, arc and S: the member's shape, free span and length on the substrate are the beam's (the
// same Hermite elements and the same crack front, node by node: equal to round-off), and the S
// span is the closed form's to within 1.5 elements, as the beam's is (contact_test.cpp).
TEST(FrameStictionTest, ACantileverMemberReleasesAsTheBeam) {
  struct Case {
    double length;
    StuckShape shape;
  };
  const int elements = 100;
  for (const Case c :
       {Case{0.95 * ArcLength(), StuckShape::kFree}, Case{1.1 * ArcLength(), StuckShape::kArc},
        Case{1.4 * StuckSpan(), StuckShape::kS}}) {
    const FrameModel model(CantileverFrame(c.length, elements));
    FrameSubstrateContact contact(model, Adhesion(kCantileverGap, kGamma));
    ReleaseDevice(model, contact);
    const ContactSummary member = contact.MemberSummary(0);
    const ContactSummary beam = ReleaseBeam(c.length, elements);
    EXPECT_EQ(member.shape, c.shape) << c.length;
    EXPECT_EQ(beam.shape, c.shape) << c.length;
    EXPECT_EQ(contact.Summary().shape, c.shape) << c.length;
    EXPECT_EQ(contact.Summary().Stuck(), c.shape != StuckShape::kFree);
    EXPECT_NEAR(member.detached_length_m, beam.detached_length_m, 1e-12 * c.length) << c.length;
    EXPECT_NEAR(member.contact_length_m, beam.contact_length_m, 1e-12 * c.length) << c.length;
    if (c.shape == StuckShape::kS) {
      EXPECT_NEAR(member.detached_length_m, StuckSpan(), 1.5 * c.length / elements);
    }
  }
}

// A finely meshed device stuck under the probe: the folded flexure of 1000 elements (125 a beam),
// its shuttle pressed down by the probe onto a substrate 2 um below it with the Casimir force on,
// sticks there (near tick 137), and every haptic step converges while the probe presses it stuck.
// A stuck node's held stiffness grows as the cube of the element count; uncapped, this press
// failed at tick 194 (Newton's matrix too ill-conditioned to converge), so it runs 210 ticks.
TEST(FrameStictionTest, AFinelyMeshedShuttleStuckUnderTheProbeKeepsStepping) {
  FoldedFlexureDesign design;
  design.elements = 125;
  const FrameModel model(FoldedFlexure(design));
  const double gap = 2e-6;
  FrameGapForce<CasimirPressure> casimir(model, CasimirPressure{}, FrameGapOptions{gap});
  ContactOptions substrate = Adhesion(gap, 1e-6);
  substrate.separation = 1e-2 * gap;
  FrameSubstrateContact contact(model, substrate);
  ForceSum forces;
  forces.Add(casimir);
  forces.Add(contact);
  HapticPhysicsOptions physics;
  physics.damping = DampingModel::QualityFactor(100);
  HapticStructure structure(model, ProbeOptions{2e-6, 50.0}, &forces, &contact, physics);
  // Into the shuttle's top face (1 um above its axis) 16 nm a tick.
  for (int tick = 0; tick < 210; ++tick) {
    const double depth = 16e-9 * tick;
    ASSERT_EQ(structure.Advance(Eigen::Vector3d(3e-6, 3e-6 - depth, 5e-6), 0.0), Status::kOk)
        << "tick " << tick;
  }
  EXPECT_EQ(contact.events().stuck, 1);
  EXPECT_EQ(contact.Summary().state, ContactState::kStuck);
  EXPECT_GT(structure.local_model().force_n, 0.0);
}

// The tip stuck alone: its energy release rate is the compliance method's p^2 theta / b, which
// for the tip-loaded cantilever held at -g is 3 E t^3 g^2 / (8 L^4) (the Hermite elements are
// exact for it; the tolerance's 1e-4 of the gap enters G twice: 2e-4 asserted, as on the beam).
TEST(FrameStictionTest, AStuckTipsEnergyReleaseRateIsTheArcShapesClosedForm) {
  const double length = 1.2 * ArcLength();
  const FrameModel model(CantileverFrame(length, 40));
  FrameSubstrateContact contact(model, Adhesion(kCantileverGap, kGamma));
  const Eigen::VectorXd d = ReleaseDevice(model, contact);
  ASSERT_EQ(contact.MemberSummary(0).shape, StuckShape::kArc);
  const int tip = static_cast<int>(contact.sites().sites().size()) - 1;
  ASSERT_TRUE(contact.sites().sites()[tip].free_end);
  const double exact = 3.0 * Stiffness() / (8.0 * std::pow(length, 4));
  EXPECT_NEAR(contact.EnergyReleaseRate(tip, d), exact, 2e-4 * exact);
  EXPECT_LT(contact.EnergyReleaseRate(tip, d), kGamma);
}

// The plate on four clamped-guided beams, pressed onto the substrate by the gap g and let go:
// it stays stuck while its springs store less than its face's adhesion, (1/2) k g^2 < Gamma A,
// and springs free past it (the beams, whose own stuck span at this Gamma is some 800 um, peel
// off first). 2 % either side of the threshold is told apart; the energy the criterion weighs
// is (1/2) k g^2 to 1e-3 (the plate lies within the tolerance, 1e-4 of the gap, of the plane, and
// the compliance's Woodbury subtraction loses some four digits of sixteen).
TEST(FrameStictionTest, APlateStaysStuckWhileItsSpringsStoreLessThanItsAdhesion) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  const double gap = 1e-6;
  const double stored = 0.5 * plate.k * gap * gap;
  const double threshold = stored / plate.area;  // J/m^2
  for (const double ratio : {0.98, 1.02}) {
    FrameSubstrateContact contact(model, Adhesion(gap, ratio * threshold));
    const Eigen::VectorXd d = ReleaseDevice(model, contact);
    const bool stuck = ratio > 1.0;
    EXPECT_EQ(contact.BodyStuck(0), stuck) << ratio;
    const double sink =
        -d[model.CarrierDof(model.mesh().body_carrier[0], 1)] * model.units().length;
    EXPECT_NEAR(sink, stuck ? gap : 0.0, 2e-4 * gap) << ratio;
    for (int m = 0; m < 4; ++m) EXPECT_FALSE(contact.MemberSummary(m).Stuck()) << ratio;
    if (stuck) {
      EXPECT_EQ(contact.Summary().shape, StuckShape::kS);
      const auto [energy, adhesion] = contact.PlateEnergies(0, d);
      EXPECT_NEAR(energy, stored, 1e-3 * stored);
      EXPECT_NEAR(adhesion, ratio * threshold * plate.area, 1e-12 * adhesion);
    } else {
      EXPECT_FALSE(contact.Summary().Stuck());
    }
  }
}

}  // namespace frame_stiction
}  // namespace
}  // namespace cosmems
