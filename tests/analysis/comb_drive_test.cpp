// Comb drives on a device (SolveCombDrives): the folded-flexure resonator driven by a comb on its
// shuttle against F / k with k = 24 E I / L^3, its capacitance, and its side instability against
// the closed form of Legtenberg et al. (1996) with the suspension's stiffnesses from the oracle
// (frame_oracle.hpp); a push-pull pair, whose forces cancel and whose negative stiffnesses add.

#include <gtest/gtest.h>

#include <cmath>

#include "structure/device_checks.hpp"

namespace cosmems {
namespace {

constexpr double kEps0 = kVacuumPermittivity;

struct DrivenFlexure {
  StructureDescription structure = test::FoldedFlexure(100e-6, 6);
  FoldedFlexureDesign design;
  int shuttle = structure.FindBody("shuttle");
  // The suspension's stiffness along x (rigid trusses and shuttle: exact) and along z, across
  // the fingers, from the oracle's dense solve.
  double kx = 0.0, kz = 0.0;

  DrivenFlexure() {
    design.material = test::Poly();
    kx = design.Stiffness();
    kz = 1e-6 / test::OracleBodyMotion(structure, shuttle, {0, 0, 1e-6})[2];
  }
  CombDrive Comb(double voltage, Eigen::Vector3d direction = Eigen::Vector3d::UnitX()) const {
    CombDrive c;
    c.body = shuttle;
    c.fingers = 20;
    c.gap = 2e-6;
    c.overlap = 10e-6;
    c.direction = direction;
    c.thickness = structure.bodies[shuttle].size.y();
    c.voltage = voltage;
    return c;
  }
};

// F = N eps0 t V^2 / g moves the shuttle F / k (the frame is exact for 24 E I / L^3 to 1e-10:
// frame_model_test.cpp), and C = 2 N eps0 t (L0 + x) / g follows it.
TEST(CombDriveTest, ACombMovesTheFoldedFlexureByForceOverStiffness) {
  const DrivenFlexure f;
  const CombDrive comb = f.Comb(30.0);
  const double force = 20 * kEps0 * 2e-6 * 900.0 / 2e-6;
  const CombDriveSolution s = SolveCombDrives(FrameModel(f.structure), {}, {comb});
  ASSERT_EQ(s.statics.status, Status::kOk);
  ASSERT_EQ(s.combs.size(), 1u);
  EXPECT_NEAR(s.combs[0].force_n, force, 1e-14 * force);
  EXPECT_NEAR(s.combs[0].engagement_m, force / f.kx, 1e-9 * force / f.kx);
  const double x = force / f.kx;
  const double c = 2 * 20 * kEps0 * 2e-6 * (10e-6 + x) / 2e-6;
  EXPECT_NEAR(s.combs[0].capacitance_f, c, 1e-9 * c);
}

// The side instability of one comb: the suspension's stiffness across the fingers k_z equals
// the comb's negative stiffness 2 N eps0 t (L0 + x) V^2 / g^3 at the engagement x = F / k_x the
// comb itself drives, a quadratic in V^2: a V^4 + b V^2 = k_z with a = 2 (N eps0 t)^2 / (g^4
// k_x), b = 2 N eps0 t L0 / g^3. The frame's k_z against the oracle's is round-off (1e-10), the
// bisection ends at 1e-15: 1e-9 asserted.
TEST(CombDriveTest, TheSideInstabilityVoltageIsLegtenbergsClosedForm) {
  const DrivenFlexure f;
  const double n_eps_t = 20 * kEps0 * 2e-6, g = 2e-6, overlap = 10e-6;
  const double a = 2 * n_eps_t * n_eps_t / (g * g * g * g * f.kx);
  const double b = 2 * n_eps_t * overlap / (g * g * g);
  const double v_squared = (-b + std::sqrt(b * b + 4 * a * f.kz)) / (2 * a);
  const double expected = std::sqrt(v_squared);
  for (double voltage : {10.0, 5000.0, -40.0}) {  // below, above and of either sign
    const CombDriveSolution s = SolveCombDrives(FrameModel(f.structure), {}, {f.Comb(voltage)});
    ASSERT_EQ(s.statics.status, Status::kOk);
    EXPECT_NEAR(s.combs[0].side_instability_voltage_v, expected, 1e-9 * expected) << voltage;
    EXPECT_NEAR(s.side_instability_factor, expected / std::abs(voltage),
                1e-9 * expected / std::abs(voltage));
  }
  // At 0 V the factor scales 1 V.
  const CombDriveSolution idle = SolveCombDrives(FrameModel(f.structure), {}, {f.Comb(0.0)});
  EXPECT_NEAR(idle.combs[0].side_instability_voltage_v, expected, 1e-9 * expected);
  EXPECT_EQ(idle.combs[0].force_n, 0.0);
}

// Two combs pulling the shuttle either way at one voltage: the forces cancel (no engagement),
// the negative stiffnesses add, 2 x 2 N eps0 t L0 V^2 / g^3 = k_z.
TEST(CombDriveTest, APushPullPairCancelsItsForcesAndAddsItsSideStiffness) {
  const DrivenFlexure f;
  const CombDriveSolution s = SolveCombDrives(
      FrameModel(f.structure), {}, {f.Comb(25.0), f.Comb(25.0, -Eigen::Vector3d::UnitX())});
  ASSERT_EQ(s.statics.status, Status::kOk);
  EXPECT_LT(std::abs(s.combs[0].engagement_m), 1e-12 * s.combs[0].force_n / f.kx);
  const double expected = std::sqrt(f.kz * 8e-18 / (4 * 20 * kEps0 * 2e-6 * 10e-6));
  EXPECT_NEAR(s.combs[0].side_instability_voltage_v, expected, 1e-9 * expected);
  EXPECT_NEAR(s.combs[1].side_instability_voltage_v, expected, 1e-9 * expected);
}

TEST(CombDriveTest, BadCombsAreRefused) {
  const DrivenFlexure f;
  const FrameModel model(f.structure);
  CombDrive lifted = f.Comb(10.0, {1.0, 0.5, 0.0});
  EXPECT_THROW(SolveCombDrives(model, {}, {lifted}), std::invalid_argument);
  CombDrive nowhere = f.Comb(10.0);
  nowhere.body = 7;
  EXPECT_THROW(SolveCombDrives(model, {}, {nowhere}), std::invalid_argument);
  CombDrive closed = f.Comb(10.0);
  closed.gap = 0.0;
  EXPECT_THROW(SolveCombDrives(model, {}, {closed}), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
