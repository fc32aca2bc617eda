// The crab-leg resonator's generator against the oracle and a closed form of extensible legs
// (both exact for point loads: round-off), and against Fedder's closed form, which takes the
// legs inextensible.
#include <gtest/gtest.h>

#include <cmath>

#include "device_checks.hpp"

namespace cosmems {
namespace {

constexpr double kCrabPull = 1e-6;  // N along x at the shuttle's centre

// Fedder's derivation keeping the members' axial strain, exact for Euler-Bernoulli members. The
// thigh, clamped at the anchor, holds the knee's turning by (E I_t / L_t) (4 - 36 / (12 + c)),
// c = (E A_s / L_s) L_t^3 / (E I_t): the shin's axial stiffness props the knee against the
// thigh's lateral bending (c -> infinity: 4, Fedder's; c = 0: 1, a free end). The shin bends
// between that spring and the guided shuttle, and the thigh's stretch adds in series.
double ExtensibleCrabLegStiffness(const CrabLegDesign& d) {
  const double e = d.material.young_modulus;
  const RectangularSection thigh{d.thigh_width, d.thickness}, shin{d.shin_width, d.thickness};
  const double ei_t = e * thigh.SecondMomentY(), ei_s = e * shin.SecondMomentY();
  const double prop = e * shin.Area() / d.shin_length * std::pow(d.thigh_length, 3) / ei_t;
  const double knee = ei_t / d.thigh_length * (4 - 36 / (12 + prop));
  const double a = ei_s / d.shin_length;
  const double bent = ei_s / std::pow(d.shin_length, 3) * (12 - 36 * a / (4 * a + knee));
  return 4 / (1 / bent + d.thigh_length / (e * thigh.Area()));
}

double CrabLegPulled(const CrabLegDesign& design) {
  return kCrabPull / test::SolveBodyMotion(CrabLeg(design), 0, {kCrabPull, 0, 0})[0];
}

TEST(CrabLegTest, TheShuttleMovesByTheClosedFormsAndTheOracles) {
  CrabLegDesign design;
  design.elements = 2;
  const StructureDescription s = CrabLeg(design);
  ASSERT_EQ(s.members.size(), 8u);
  ASSERT_EQ(s.bodies.size(), 1u);
  const test::BodyMotion moved = test::SolveBodyMotion(s, 0, {kCrabPull, 0, 0});
  const test::BodyMotion oracle = test::OracleBodyMotion(s, 0, {kCrabPull, 0, 0});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(moved[k], oracle[k], 1e-9 * moved[0]);
  EXPECT_NEAR(moved[4], 0.0, 1e-9 * moved[0] / design.shin_length);  // the shuttle does not turn
  const double k = kCrabPull / moved[0];
  EXPECT_NEAR(k, ExtensibleCrabLegStiffness(design), 1e-9 * k);
  // Fedder's k: the short, wide thigh is stiff laterally, 1/20 of the shin's axial stiffness,
  // so the prop it takes rigid gives: measured 1.38e-3 above the frame.
  EXPECT_NEAR(k, design.Stiffness(), 2e-3 * k);

  // Longer, narrower legs, the shin propping the knee 250 times as stiffly as the thigh bends
  // laterally: measured 3.5e-4.
  design.shin_length = 150e-6;
  design.thigh_length = 80e-6;
  design.thigh_width = 3e-6;
  const double longer = CrabLegPulled(design);
  EXPECT_NEAR(longer, ExtensibleCrabLegStiffness(design), 1e-9 * longer);
  EXPECT_NEAR(longer, design.Stiffness(), 5e-4 * longer);
}

// A thigh twenty times wider than the shin turns its knee by almost nothing: the shins are
// clamped-guided, 4 x 12 E I_s / L_s^3. Fedder's form leaves 3.7e-5 of the thigh's compliance;
// the frame 1.5e-4, as the extensible legs say: a thigh this stiff laterally is no longer
// propped by the shin, and holds the knee by about E I_t / L_t, not 4 E I_t / L_t.
TEST(CrabLegTest, ARigidThighLeavesClampedGuidedShins) {
  CrabLegDesign design;
  design.elements = 2;
  design.thigh_width = 40e-6;
  const double ei =
      design.material.young_modulus * design.thickness * std::pow(design.shin_width, 3) / 12;
  const double guided = 4 * 12 * ei / std::pow(design.shin_length, 3);
  EXPECT_NEAR(design.Stiffness(), guided, 4e-5 * guided);
  EXPECT_LT(design.Stiffness(), guided);
  const double k = CrabLegPulled(design);
  EXPECT_NEAR(k, ExtensibleCrabLegStiffness(design), 1e-9 * k);
  EXPECT_NEAR(k, guided, 2e-4 * guided);
  EXPECT_LT(k, guided);
}

// The modes against the oracle at order 0 (same matrices), and at order 1 against the oracle's
// Hermite mesh at 32 elements per member (measured within 4.7e-8, about the oracle's own h^4
// error there; at 16 it is 5.8e-7); the shuttle's mode bends the shins in the plane, below
// sqrt(k / m) of the shuttle alone (the legs add mass).
TEST(CrabLegTest, ItsModesAreTheOraclesAndTheShuttleModeBendsTheShins) {
  CrabLegDesign design;
  design.elements = 3;
  test::ExpectModesMatchOracle(CrabLeg(design), 8);

  design.elements = 4;
  const StructureDescription s = CrabLeg(design);
  StructureDescription fine = s;
  for (StructureMember& m : fine.members) m.elements = 32;
  const Eigen::VectorXd converged = test::oracle::Frequencies(test::ToOracle(fine), 6);
  ModalOptions options;
  options.count = 6;
  const FrameModalResult modes = SolveFrameModal(FrameModel(s), options);
  ASSERT_EQ(modes.modal.status, Status::kOk);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(modes.modal.modes[i].frequency_hz, converged[i], 1e-7 * converged[i])
        << "mode " << i;
  }
  const std::size_t shuttle = test::ModeAlong(modes, 0);
  EXPECT_EQ(modes.modal.modes[shuttle].kind, ModeKind::kBendingZ);
  const double bound = std::sqrt(design.Stiffness() / s.bodies[0].Mass()) / (2 * kPi);
  EXPECT_LT(modes.modal.modes[shuttle].frequency_hz, bound);
}

TEST(CrabLegTest, ParameterErrorsNameTheirKey) {
  auto field = [](void (*change)(CrabLegDesign&)) {
    CrabLegDesign design;
    change(design);
    return test::ErrorField(&CrabLeg, design);
  };
  EXPECT_EQ(field([](CrabLegDesign&) {}), "built");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.thigh_length = 0; }), "structure.thigh_length");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.thigh_width = -1e-6; }), "structure.thigh_width");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.shin_length = 0; }), "structure.shin_length");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.shin_width = 0; }), "structure.shin_width");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.shuttle_length = 0; }), "structure.shuttle_length");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.thickness = 0; }), "structure.thickness");
  // Too narrow for two shins side by side; a thigh wider than twice the shin reaches the shuttle.
  EXPECT_EQ(field([](CrabLegDesign& d) { d.shuttle_width = 4e-6; }), "structure.shuttle_width");
  EXPECT_EQ(field([](CrabLegDesign& d) { d.shin_length = 1.5e-6; }), "structure.shin_length");
}

}  // namespace
}  // namespace cosmems
