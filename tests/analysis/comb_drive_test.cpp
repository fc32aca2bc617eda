// Comb drives on a device (SolveCombDrives): the folded-flexure resonator driven by a comb on its
// shuttle against F / k with k = 24 E I / L^3, its capacitance, and its side instability against
// the closed form of Legtenberg et al. (1996) with the suspension's stiffnesses from the oracle
// (frame_oracle.hpp); a push-pull pair, whose forces cancel and whose negative stiffnesses add.
// The combs as a nonlinear force (CombDriveForce): its force and tangent against differences of
// its co-energy, Newton's statics and bisected side instability against the closed forms, and
// fingers pushed off centre against the two equilibrium equations solved in the test.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "force_differences.hpp"
#include "structure/device_checks.hpp"

namespace cosmems {
namespace {

constexpr double kEps0 = kVacuumPermittivity;

// A force that adds nothing: it puts SolveCombDrives on its nonlinear path with the same physics.
class NoFrameForce final : public FrameElementForce {
 public:
  bool Evaluate(const Eigen::VectorXd&, Eigen::VectorXd&, ForceTangent&) override { return true; }
  FrameModel::ElementVector LocalForce(const Eigen::VectorXd&, int) const override {
    return FrameModel::ElementVector::Zero();
  }
};

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

// The closed-form side-instability voltage of DrivenFlexure's comb (the test above).
double LegtenbergVoltage(const DrivenFlexure& f) {
  const double n_eps_t = 20 * kEps0 * 2e-6, g = 2e-6, overlap = 10e-6;
  const double a = 2 * n_eps_t * n_eps_t / (g * g * g * g * f.kx);
  const double b = 2 * n_eps_t * overlap / (g * g * g);
  return std::sqrt((-b + std::sqrt(b * b + 4 * a * f.kz)) / (2 * a));
}

// r = -grad(V^2 C / 2) and its tangent against central differences of the co-energy and of r,
// with the shuttle moved along and across the fingers (a third of the gap) so that every term
// of the Hessian counts. Steps of 1e-4 of the motion: truncation (h^2) and round-off both near
// 1e-8 of the force; 1e-6 asserted.
TEST(CombDriveTest, TheCombForceAndItsTangentAreTheCoEnergysDerivatives) {
  const DrivenFlexure f;
  const FrameModel model(f.structure);
  const CombDrive comb = f.Comb(120.0, Eigen::Vector3d(1.0, 0.0, 1.0));
  CombDriveForce force(model, {comb});
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const int carrier = model.mesh().body_carrier[f.shuttle];
  const double length = model.units().length;
  d[model.CarrierDof(carrier, 0)] = 1e-6 / length;
  d[model.CarrierDof(carrier, 2)] = -0.2e-6 / length;
  const Eigen::Vector2d xy = force.Motion(d, 0);  // across: (1, 0, -1) / sqrt(2)
  EXPECT_NEAR(xy[0], 0.8e-6 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(xy[1], 1.2e-6 / std::sqrt(2.0), 1e-15);
  const double to_internal = model.units().force * length;
  const auto energy = [&](const Eigen::VectorXd& at) {
    const Eigen::Vector2d m = force.Motion(at, 0);
    return -0.5 * 120.0 * 120.0 * comb.Capacitance(m[0], m[1]) / to_internal;
  };
  test::ExpectForceAndTangentMatchDifferences(force, d, model.Stiffness().bandwidth(), energy,
                                              1e-4 * 1e-6 / length, 1e-6);
  // Beyond the model: a finger on its neighbour, fingers apart.
  Eigen::VectorXd r = Eigen::VectorXd::Zero(d.size());
  ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
  d[model.CarrierDof(carrier, 2)] = -3e-6 / length;
  EXPECT_FALSE(force.Evaluate(d, r, tangent));
  d[model.CarrierDof(carrier, 0)] = d[model.CarrierDof(carrier, 2)] = -8e-6 / length;
  EXPECT_FALSE(force.Evaluate(d, r, tangent));
}

// With any other force the combs are a CombDriveForce in Newton's statics and the instability
// is bisected on the tangent's definiteness: centred, the same engagement as the linear path
// (Newton's tolerance, 1e-9 asserted) and Legtenberg's voltage (the bisection stops at 1e-10;
// 1e-8 asserted); a second comb pulling back gives the push-pull pair's voltage.
TEST(CombDriveTest, NewtonsStaticsAndBisectionGiveTheClosedForms) {
  const DrivenFlexure f;
  const FrameModel model(f.structure);
  NoFrameForce nothing;
  const CombDriveSolution linear = SolveCombDrives(model, {}, {f.Comb(30.0)});
  const CombDriveSolution s = SolveCombDrives(model, {}, {f.Comb(30.0)}, {&nothing});
  ASSERT_EQ(s.statics.status, Status::kOk);
  EXPECT_NEAR(s.combs[0].engagement_m, linear.combs[0].engagement_m,
              1e-9 * linear.combs[0].engagement_m);
  EXPECT_NEAR(s.combs[0].force_n, linear.combs[0].force_n, 1e-14 * linear.combs[0].force_n);
  EXPECT_NEAR(s.combs[0].capacitance_f, linear.combs[0].capacitance_f,
              1e-9 * linear.combs[0].capacitance_f);
  const double expected = LegtenbergVoltage(f);
  EXPECT_NEAR(s.combs[0].side_instability_voltage_v, expected, 1e-8 * expected);
  // The last stable state sits just below it, its engagement F / k_x there.
  const double below = s.last_stable_factor * 30.0;
  EXPECT_NEAR(below, expected, 1e-8 * expected);
  const double engaged = f.Comb(below).Force(below) / f.kx;
  EXPECT_NEAR(s.last_stable.bodies[f.shuttle][0], engaged, 1e-8 * engaged);
  EXPECT_NEAR(linear.last_stable.bodies[f.shuttle][0], engaged, 1e-8 * engaged);

  const CombDriveSolution pair = SolveCombDrives(
      model, {}, {f.Comb(25.0), f.Comb(25.0, -Eigen::Vector3d::UnitX())}, {&nothing});
  ASSERT_EQ(pair.statics.status, Status::kOk);
  const double paired = std::sqrt(f.kz * 8e-18 / (4 * 20 * kEps0 * 2e-6 * 10e-6));
  EXPECT_NEAR(pair.combs[1].side_instability_voltage_v, paired, 1e-8 * paired);
}

// A side load F pushes the shuttle y across its fingers, and the fingers pull it further:
//   k_x x = V^2 q (1/(g-y) + 1/(g+y)) / 2,   k_z y = F + V^2 q (L0 + x) (1/(g-y)^2 - 1/(g+y)^2) / 2
// (q = N eps0 t), the suspension's stiffnesses decoupled by its symmetry, solved here by Newton
// on the pair. At 0.9 of the side-instability voltage and F = 0.03 k_z g the offset is a twentieth
// of the gap and more than 2 % above the linearised comb's; Newton's statics meet the pair to 1e-7
// (k_z's round-off 1e-10, the statics' tolerance 1e-8).
TEST(CombDriveTest, FingersPushedOffCentrePullTheShuttleFurther) {
  const DrivenFlexure f;
  const double v = 0.9 * LegtenbergVoltage(f), g = 2e-6, overlap = 10e-6;
  const double q = 20 * kEps0 * 2e-6, side = 0.03 * f.kz * g;
  FrameLoadCase loads;
  const Eigen::Vector3d across = f.Comb(v).Lateral();
  loads.points.push_back({-1, f.shuttle, side * across, Eigen::Vector3d::Zero()});
  NoFrameForce nothing;
  const CombDriveSolution s =
      SolveCombDrives(FrameModel(f.structure), loads, {f.Comb(v)}, {&nothing});
  ASSERT_EQ(s.statics.status, Status::kOk);
  Eigen::Vector2d xy(0.0, 0.0);
  for (int i = 0; i < 50; ++i) {
    const double x = xy[0], y = xy[1], a = 1 / (g - y), b = 1 / (g + y);
    const double h = 0.5 * v * v * q;
    const Eigen::Vector2d residual(f.kx * x - h * (a + b),
                                   f.kz * y - side - h * (overlap + x) * (a * a - b * b));
    Eigen::Matrix2d jacobian;
    jacobian << f.kx, -h * (a * a - b * b), -h * (a * a - b * b),
        f.kz - 2 * h * (overlap + x) * (a * a * a + b * b * b);
    xy -= jacobian.lu().solve(residual);
  }
  EXPECT_NEAR(s.combs[0].engagement_m, xy[0], 1e-7 * xy[0]);
  EXPECT_NEAR(s.combs[0].offset_m, xy[1], 1e-7 * xy[1]);
  EXPECT_NEAR(s.statics.bodies[f.shuttle].head<3>().dot(across), xy[1], 1e-7 * xy[1]);
  const double linearised = side / (f.kz - f.Comb(v).SideStiffness(v, xy[0]));
  std::printf("off centre: %.6e m, linearised comb %.6e m\n", xy[1], linearised);
  EXPECT_GT(xy[1], 1.02 * linearised);
  EXPECT_NEAR(s.combs[0].force_n, f.Comb(v).Force(v, xy[1]), 1e-12 * s.combs[0].force_n);
}

// Under the "stretching" theory the suspension softens across the fingers as the comb pulls the
// shuttle along them. At a constant engagement force each clamped-guided beam, swayed by
// d = x/2, adds to its axial compliance L/EA what its sway's foreshortening gives back under an
// axial load, d^2 L/EI (3/25 + 1/700): 3/25 from the load's geometric stiffness 6P/5L, which
// changes the sway the constant force holds, and 1/700 the elastokinematic term at a fixed sway
// (Awtar's beam constraint model). Two beams in series in each of four folds give
// k_z(x) = 2 / (L/EA + (x/2)^2 L/EI (3/25 + 1/700)), and the side instability lies where
// 2 q V^2 (L0 + x) / g^3 = k_z(x) at x = q V^2 / (g k_x), found here by bisection. The closed
// form is first order in the sway (x/2L = 0.065 there): 1 % asserted.
TEST(CombDriveTest, StretchingSoftensTheSuspensionAcrossTheFingers) {
  const DrivenFlexure f;
  const FrameModel model(f.structure, FrameCouplings::kStretching);
  FrameStretchingForce stretching(model);
  const CombDriveSolution s = SolveCombDrives(model, {}, {f.Comb(30.0)}, {&stretching});
  ASSERT_EQ(s.statics.status, Status::kOk);
  const double e = f.design.material.young_modulus, w = f.design.beam_width;
  const double t = f.design.thickness, l = f.design.beam_length;
  const double ea = e * w * t, ei = e * t * w * w * w / 12.0;
  const double q = 20 * kEps0 * t, g = 2e-6, overlap = 10e-6;
  const auto excess = [&](double v) {
    const double x = q * v * v / (g * f.kx), sway = 0.5 * x;
    const double kz = 2.0 / (l / ea + sway * sway * l / ei * (3.0 / 25.0 + 1.0 / 700.0));
    return 2 * q * v * v * (overlap + x) / (g * g * g) - kz;
  };
  double lo = 1.0, hi = LegtenbergVoltage(f);
  while (hi - lo > 1e-9 * hi) (excess(0.5 * (lo + hi)) < 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double voltage = s.combs[0].side_instability_voltage_v;
  std::printf("side instability under stretching: %.6g V, first-order closed form %.6g V\n",
              voltage, lo);
  EXPECT_NEAR(voltage, lo, 1e-2 * lo);
  EXPECT_LT(voltage, 0.5 * LegtenbergVoltage(f));
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
