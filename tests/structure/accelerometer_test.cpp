// The guided proof-mass accelerometer's generator: along x each beam is clamped-guided, and a
// transverse end displacement stretches no Euler-Bernoulli member, so the proof mass moves by
// m a / (4 x 12 E I / L^3) to round-off (1e-9), as by the oracle. Its frequency against
// sqrt(k / m) with m the proof mass alone, which the beams' mass lowers by about 13/70 of their
// share (0.4 % at the defaults).
#include <gtest/gtest.h>

#include <cmath>

#include "device_checks.hpp"

namespace cosmems {
namespace {

constexpr double kGravity = 9.80665;  // m/s^2

TEST(AccelerometerTest, TheProofMassMovesByMAOverK) {
  AccelerometerDesign design;
  design.elements = 2;
  const StructureDescription s = Accelerometer(design);
  ASSERT_EQ(s.members.size(), 4u);
  EXPECT_EQ(s.bodies[0].Mass(), design.ProofMass());
  const Eigen::Vector3d inertial(design.ProofMass() * kGravity, 0, 0);
  const test::BodyMotion moved = test::SolveBodyMotion(s, 0, inertial);
  const test::BodyMotion oracle = test::OracleBodyMotion(s, 0, inertial);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(moved[k], oracle[k], 1e-9 * moved[0]);
  const double expected = design.Displacement(kGravity);
  EXPECT_NEAR(moved[0], expected, 1e-9 * expected);
  EXPECT_NEAR(inertial.x() / moved[0], design.Stiffness(), 1e-9 * design.Stiffness());

  design.beam_length = 250e-6;
  design.beam_width = 3e-6;
  design.mass_width = 300e-6;
  const double longer =
      test::SolveBodyMotion(Accelerometer(design), 0, {design.ProofMass() * kGravity, 0, 0})[0];
  EXPECT_NEAR(longer, design.Displacement(kGravity), 1e-9 * longer);
}

TEST(AccelerometerTest, ItSensesAtSqrtKOverMLessTheBeamsShare) {
  const AccelerometerDesign design;
  const StructureDescription s = Accelerometer(design);
  ModalOptions options;
  options.count = 4;
  const FrameModalResult modes = SolveFrameModal(FrameModel(s), options);
  ASSERT_EQ(modes.modal.status, Status::kOk);
  const std::size_t sensing = test::ModeAlong(modes, 0);
  EXPECT_EQ(modes.modal.modes[sensing].kind, ModeKind::kBendingZ);
  const double f = modes.modal.modes[sensing].frequency_hz;
  // The beams weigh 2.3 % of the proof mass: measured 0.42 % below sqrt(k / m) / 2 pi.
  EXPECT_LT(f, design.NaturalFrequency());
  EXPECT_NEAR(f, design.NaturalFrequency(), 0.01 * design.NaturalFrequency());
  // With 13/35 of the beams' mass (Rayleigh, their static shape, which bounds it from above):
  // measured 1.1e-6 below.
  const double beams =
      4 * design.material.density * design.beam_width * design.thickness * design.beam_length;
  const double rayleigh =
      std::sqrt(design.Stiffness() / (design.ProofMass() + 13.0 / 35.0 * beams)) / (2 * kPi);
  EXPECT_NEAR(f, rayleigh, 1e-5 * rayleigh);
  test::ExpectModesMatchOracle(Accelerometer(design), 6);
}

TEST(AccelerometerTest, ParameterErrorsNameTheirKey) {
  auto field = [](void (*change)(AccelerometerDesign&)) {
    AccelerometerDesign design;
    change(design);
    return test::ErrorField(&Accelerometer, design);
  };
  EXPECT_EQ(field([](AccelerometerDesign&) {}), "built");
  EXPECT_EQ(field([](AccelerometerDesign& d) { d.beam_length = 0; }), "structure.beam_length");
  EXPECT_EQ(field([](AccelerometerDesign& d) { d.beam_width = 0; }), "structure.beam_width");
  EXPECT_EQ(field([](AccelerometerDesign& d) { d.mass_length = -1.0; }), "structure.mass_length");
  // Too narrow for two beams side by side.
  EXPECT_EQ(field([](AccelerometerDesign& d) { d.mass_width = 3e-6; }), "structure.mass_width");
}

}  // namespace
}  // namespace cosmems
