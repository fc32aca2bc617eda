// analysis.type = "pullin" through the CLI: the embedded cantilever against Osterberg &
// Senturia's closed form, what fringing fields, surface forces and stretching change, the search
// bound, and the files. The solver's accuracy against independent solutions is held by
// tests/surface/pullin_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "cosmems/surface/gap_pressures.hpp"

namespace cosmems {
namespace {

using testing::Cli;
using testing::ExpectContains;
using testing::ReadLines;
using testing::RunJson;
using testing::TempDirectory;

double Voltage(std::vector<std::string> args) {
  const nlohmann::json json = RunJson(std::move(args));
  EXPECT_EQ(json.at("status"), "ok");
  return json.at("pullin_voltage_v").get<double>();
}

// V = sqrt(0.28 E t^3 g^3 / (eps0 L^4)) for a wide cantilever without fringing, quoted to two
// digits: within 0.5 %. A cantilever pulls in at 0.45 of its gap.
TEST(PullinCliTest, CantileverMatchesOsterbergAndSenturia) {
  const Scene scene = LoadScene("cantilever-pullin");
  const double g = *scene.structure.gap;
  const double expected =
      std::sqrt(0.28 * scene.material.young_modulus * std::pow(scene.structure.thickness, 3) *
                std::pow(g, 3) / (kVacuumPermittivity * std::pow(scene.structure.length, 4)));
  const nlohmann::json json = RunJson({"cantilever-pullin"});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("analysis"), "pullin");
  EXPECT_NEAR(json.at("pullin_voltage_v").get<double>(), expected, 5e-3 * expected);
  const double travel = json.at("pullin_travel_m").get<double>();
  EXPECT_NEAR(travel / g, 0.4465, 1e-3);
  const double stable = json.at("pullin_displacement_m").get<double>();
  EXPECT_LE(stable, travel);
  EXPECT_GT(stable, 0.99 * travel);
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

// Each added pull lowers the voltage: fringing fields (which add 0.65 d / b to the pressure) by
// about 2 %, the surface forces at a 2 um gap by far less. A residual tension raises it.
TEST(PullinCliTest, FringingSurfaceForcesAndTensionMoveThePullInVoltage) {
  const double plain = Voltage({"cantilever-pullin"});
  const double fringing =
      Voltage({"cantilever-pullin", "--set", "effects.electrostatic.fringing=true"});
  EXPECT_LT(fringing, 0.99 * plain);
  EXPECT_GT(fringing, 0.95 * plain);
  const double surface = Voltage({"cantilever-pullin", "--set", "effects.casimir={}", "--set",
                                  "effects.van_der_waals={hamaker=1e-19}"});
  EXPECT_LT(surface, plain);
  EXPECT_GT(surface, 0.999 * plain);
  const std::vector<std::string> bridge = {"cantilever-pullin", "--set", "structure.kind=bridge"};
  const double linear = Voltage(bridge);
  std::vector<std::string> tension = bridge;
  tension.insert(tension.end(), {"--set", "structure.axial_load=1e-3"});
  EXPECT_GT(Voltage(tension), 1.05 * linear);
  std::vector<std::string> stretching = bridge;
  stretching.insert(stretching.end(), {"--set", "model.theory=stretching"});
  EXPECT_GT(Voltage(stretching), 1.02 * linear);
}

// The strongly stretched bridge (100 um long, 2 um thick over a 4 um gap): the stretching
// stiffens its path until the fold sits at 0.56 of the gap, and the search reaches it, with a
// voltage bound above the answer as without one (the shooting solution: 1370.66 V). A bound below
// it is a numerical status, as for any beam.
TEST(PullinCliTest, StronglyStretchedBridgePullsInWithOrWithoutABound) {
  const std::vector<std::string> bridge = {
      "cantilever-pullin",       "--set", "structure.kind=bridge", "--set",
      "structure.length=100e-6", "--set", "structure.gap=4e-6",    "--set",
      "model.theory=stretching"};
  const nlohmann::json json = RunJson(bridge);
  ASSERT_EQ(json.at("status"), "ok");
  const double voltage = json.at("pullin_voltage_v").get<double>();
  EXPECT_NEAR(voltage, 1370.66, 1e-4 * 1370.66);
  EXPECT_NEAR(json.at("pullin_travel_m").get<double>() / 4e-6, 0.5585, 1e-3);
  EXPECT_EQ(json.at("pullin_instability"), "limit_point");
  std::vector<std::string> bounded = bridge;
  bounded.insert(bounded.end(), {"--set", "analysis.voltage_max=2000.0"});
  EXPECT_DOUBLE_EQ(Voltage(bounded), voltage);
  bounded.back() = "analysis.voltage_max=1300.0";
  EXPECT_EQ(RunJson(bounded, 3).at("status"), "not converged");
}

TEST(PullinCliTest, NoPullInBelowTheBoundIsANumericalStatus) {
  const nlohmann::json json =
      RunJson({"cantilever-pullin", "--set", "analysis.voltage_max=10.0"}, 3);
  EXPECT_EQ(json.at("status"), "not converged");
  ASSERT_EQ(json.at("warnings").size(), 1u);
  ExpectContains(json["warnings"][0], "no pull-in below analysis.voltage_max = 10 V");
  EXPECT_FALSE(json.contains("pullin_voltage_v"));
}

TEST(PullinCliTest, OutWritesTheLastStableShape) {
  const TempDirectory dir;
  const nlohmann::json json = RunJson({"cantilever-pullin", "--out", dir.path().string()});
  const std::vector<std::string> lines = ReadLines(dir.path() / "pullin_shape.csv");
  ASSERT_EQ(lines.size(), 1u + 21u);
  EXPECT_EQ(lines[0], "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  const std::string tip = lines.back();
  const double uy = std::stod(tip.substr(tip.find(',', tip.find(',') + 1) + 1));
  EXPECT_NEAR(-uy, json.at("pullin_displacement_m").get<double>(), 1e-9 * std::abs(uy));
}

TEST(PullinCliTest, WarnsAboutSettingsThatDoNotChangeIt) {
  const nlohmann::json json =
      RunJson({"cantilever-pullin", "--set", "effects.electrostatic.voltage=5.0", "--set",
               "loads.tip_force=[0, -1e-7, 0]"});
  ASSERT_EQ(json.at("warnings").size(), 2u);
  ExpectContains(json["warnings"].dump(), "the voltage is what the analysis finds");
  ExpectContains(json["warnings"].dump(), "the pull-in voltage is the unloaded beam's");
}

}  // namespace
}  // namespace cosmems
