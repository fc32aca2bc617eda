// Electrodes under a device from the CLI: the embedded serpentine-pullin scene pulls in at the
// parallel-plate voltage of its springs' stiffness (the serpentine's Castigliano form, exact for
// the frame to 1e-12); below it the static analysis finds where the plate rests and its
// capacitance; effects that a device cannot take, or electrodes where a scene cannot have them,
// are refused naming the key.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_test_support.hpp"
#include "cosmems/structure/serpentine.hpp"

namespace cosmems {
namespace {

using testing::ExpectContains;
using testing::InvalidInput;
using testing::RunJson;

constexpr double kEps0 = 8.8541878128e-12, kGap = 2e-6, kArea = 100e-6 * 100e-6;

double SpringStiffness() {
  SerpentineDesign design;
  design.material = Material{160e9, 2330.0, 0.22};
  return design.Stiffness();
}

// V = sqrt(8 k g^3 / (27 eps0 A)): the fold search leaves ~1e-7 (pullin_test.cpp), the frame's
// stiffness 1e-12; 1e-5 bounds both with room.
TEST(DevicePullInCliTest, SerpentinePlatePullsInAtTheParallelPlateVoltage) {
  const nlohmann::json json = RunJson({"serpentine-pullin"});
  ASSERT_EQ(json["status"], "ok");
  const double k = SpringStiffness();
  const double v = std::sqrt(8.0 * k * kGap * kGap * kGap / (27.0 * kEps0 * kArea));
  EXPECT_NEAR(json["pullin_voltage_v"].get<double>(), v, 1e-5 * v);
  EXPECT_NEAR(json["pullin_travel_m"].get<double>(), kGap / 3.0, 1e-3 * kGap);
  EXPECT_EQ(json["pullin_instability"], "limit_point");
  EXPECT_EQ(json["pullin_point"]["name"], "plate");
  const double c = kEps0 * kArea / kGap;
  EXPECT_NEAR(json["capacitance_f"]["electrostatic"].get<double>(), c, 1e-12 * c);
  const double x = -json["bodies"]["plate"]["displacement"][1].get<double>();
  EXPECT_NEAR(x, kGap / 3.0, 2e-3 * kGap);
  EXPECT_NEAR(json["pullin_displacement_m"].get<double>(), x, 1e-2 * x);  // corners tilt nothing
  const testing::CliOutcome text = testing::Cli({"run", "serpentine-pullin"});
  EXPECT_EQ(text.code, 0);
  ExpectContains(text.out, "travel held at        plate ");
}

// At 10 V the plate rests where k x = eps0 A V^2 / 2 (g - x)^2 (bisection here), with the
// capacitance eps0 A / (g - x); at 20 V, above pull-in, there is no equilibrium: exit 3 and a
// warning that says so.
TEST(DevicePullInCliTest, BelowPullInThePlateRestsWhereItsSpringsHoldIt) {
  const nlohmann::json json = RunJson({"serpentine-pullin", "--set", "analysis.type=\"static\""});
  ASSERT_EQ(json["status"], "ok");
  const double k = SpringStiffness(), v = 10.0;
  const auto excess = [&](double x) {
    return k * x - kEps0 * kArea * v * v / (2.0 * (kGap - x) * (kGap - x));
  };
  double lo = 0.0, hi = kGap / 3.0;
  for (int i = 0; i < 200; ++i) ((excess(0.5 * (lo + hi)) < 0.0) ? lo : hi) = 0.5 * (lo + hi);
  const double x = 0.5 * (lo + hi);
  EXPECT_NEAR(-json["bodies"]["plate"]["displacement"][1].get<double>(), x, 1e-8 * x);
  const double c = kEps0 * kArea / (kGap - x);
  EXPECT_NEAR(json["capacitance_f"]["electrostatic"].get<double>(), c, 1e-8 * c);
  const nlohmann::json above = RunJson({"serpentine-pullin", "--set", "analysis.type=\"static\"",
                                        "--set", "effects.electrostatic.voltage=20.0"},
                                       3);
  EXPECT_EQ(above["status"], "not converged");
  ExpectContains(above["warnings"].dump(), "pulls in below it");
}

// A transient under the electrode: 10 V switched on at t = 0 swings the plate past its rest
// (a suddenly applied load overshoots) and no further than twice it (damping takes some), and
// the plate is what the run watches.
TEST(DevicePullInCliTest, AVoltageSwitchedOnSwingsThePlate) {
  const nlohmann::json statics =
      RunJson({"serpentine-pullin", "--set", "analysis.type=\"static\""});
  const double rest = -statics["bodies"]["plate"]["displacement"][1].get<double>();
  const nlohmann::json json =
      RunJson({"serpentine-pullin", "--set", "analysis.type=\"transient\"", "--set",
               "analysis.duration=1e-4", "--set", "analysis.time_step=2e-7", "--set",
               "effects.damping.quality_factor=5.0"});
  ASSERT_EQ(json["status"], "ok");
  EXPECT_EQ(json["watched"]["point"], "plate");
  EXPECT_EQ(json["watched"]["component"], "uy");
  EXPECT_GT(json["displacement_max"].get<double>(), rest);
  EXPECT_LT(json["displacement_max"].get<double>(), 2.0 * rest);
}

TEST(DevicePullInCliTest, ElectrodesWhereTheyCannotActAreRefused) {
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set",
                               "effects.electrostatic.electrodes=[{x=[-50e-6,50e-6],z=[-50e-6,"
                               "50e-6]},{x=[0.0,60e-6],z=[0.0,1e-6]}]"}),
                 "effects.electrostatic.electrodes[1]");
  ExpectContains(
      InvalidInput({"run", "serpentine-pullin", "--set",
                    "effects.electrostatic.electrodes=[{x=[50e-6,-50e-6],z=[0.0,1e-6]}]"}),
      "effects.electrostatic.electrodes[0].x");
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set",
                               "effects.electrostatic.electrode_start=0.0"}),
                 "effects.electrostatic.electrode_start");
  ExpectContains(InvalidInput({"run", "cantilever-pullin", "--set",
                               "effects.electrostatic.electrodes=[{x=[0.0,1e-4],z=[0.0,1e-6]}]"}),
                 "effects.electrostatic.electrodes");
  ExpectContains(
      InvalidInput({"run", "serpentine-pullin", "--set", "effects.stiction.adhesion_energy=0.02"}),
      "effects.stiction");
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set", "analysis.type=\"modal\""}),
                 "effects.electrostatic");
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set", "structure.gap=false"}),
                 "structure.gap");
  ExpectContains(
      InvalidInput({"run", "serpentine-pullin", "--set", "effects.electrostatic.ac_voltage=1.0"}),
      "effects.electrostatic.ac_voltage");
}

}  // namespace
}  // namespace cosmems
