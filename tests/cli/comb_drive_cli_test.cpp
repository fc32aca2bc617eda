// [[effects.combs]] on a device from the CLI: the folded-flexure resonator driven by a comb on
// its shuttle moves F / k; the capacitance and the side-instability voltage are in the JSON;
// combs where a scene cannot take them are refused naming the key.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace cosmems {
namespace {

using testing::ExpectContains;
using testing::InvalidInput;
using testing::RunJson;
using testing::TempDirectory;
using testing::WriteFile;

constexpr const char* kDrivenFlexure = R"(
[structure]
kind = "folded_flexure"
thickness = 2e-6
[material]
young_modulus = 160e9
density = 2330.0
poisson_ratio = 0.22
[model]
elements = 6
[[effects.combs]]
body = "shuttle"
fingers = 20
gap = 2e-6
overlap = 10e-6
voltage = 30.0
[analysis]
type = "static"
)";

// F = N eps0 t V^2 / g against k = 24 E I / L^3 = 2 E t w^3 / L^3 (the frame is exact for it to
// 1e-10); C = 2 N eps0 t (L0 + x) / g.
TEST(CombDriveCliTest, ACombDrivesTheFoldedFlexureByForceOverStiffness) {
  const TempDirectory dir;
  const std::string scene = (dir.path() / "driven.toml").string();
  WriteFile(scene, kDrivenFlexure);
  const nlohmann::json json = RunJson({scene});
  ASSERT_EQ(json["status"], "ok");
  const double eps0 = 8.8541878128e-12, k = 2 * 160e9 * 2e-6 * 8e-18 / 1e-12;
  const double force = 20 * eps0 * 2e-6 * 900.0 / 2e-6, x = force / k;
  EXPECT_NEAR(json["combs"][0]["force_n"].get<double>(), force, 1e-12 * force);
  EXPECT_EQ(json["combs"][0]["body"], "shuttle");
  EXPECT_NEAR(json["combs"][0]["engagement_m"].get<double>(), x, 1e-9 * x);
  EXPECT_NEAR(json["bodies"]["shuttle"]["displacement"][0].get<double>(), x, 1e-9 * x);
  const double c = 2 * 20 * eps0 * 2e-6 * (10e-6 + x) / 2e-6;
  EXPECT_NEAR(json["capacitance_f"]["combs"][0].get<double>(), c, 1e-9 * c);
  // The suspension is much stiffer across the fingers (its beams' axial stiffness) than along
  // them: the side instability lies far above the drive's 30 V.
  EXPECT_GT(json["side_instability_voltage_v"][0].get<double>(), 300.0);
  const testing::CliOutcome text = testing::Cli({"run", scene});
  EXPECT_EQ(text.code, 0);
  ExpectContains(text.out, "comb 0 on shuttle  force ");
}

// The driven flexure as a modal transient of `duration` and `step` (six modes), with `extra`
// keys in its comb's entry and `more` after [analysis].
std::string Transient(double duration, double step, const std::string& extra = "",
                      const std::string& more = "") {
  std::string text = kDrivenFlexure;
  text.replace(text.find("voltage = 30.0"), 14, "voltage = 30.0\n" + extra);
  char analysis[240];
  std::snprintf(analysis, sizeof analysis,
                "type = \"transient\"\nintegrator = \"modal\"\nduration = %.17g\n"
                "time_step = %.17g\nrecord = [\"shuttle\"]\n",
                duration, step);
  text.replace(text.find("type = \"static\""), 15, analysis);
  return text + more;
}

// In a transient a comb at a constant voltage is its force applied at rest: the same run as
// [[loads.points]] with F = N eps0 t V^2 / g on the shuttle. Driven at the shuttle's frequency
// by V = 30 + sin(w t) V with Q = 50, the shuttle swings about its mean offset
// N eps0 t (V_dc^2 + V_ac^2 / 2) / g / k by about Q times the push at w over k,
// 2 N eps0 t V_dc V_ac / g / k: the single mode's estimate, which the beams' mass, the other
// modes and the peak's sampling (100 steps a period) move by a little (measured 2.0 % of the
// swing, 4 % asserted; the library's test holds the run to the oracle's every mode).
TEST(CombDriveCliTest, ACombDrivesATransientAtItsVoltageInTime) {
  const TempDirectory dir;
  const double eps0 = 8.8541878128e-12, c = 20 * eps0 * 2e-6 / 2e-6;
  const double k = 2 * 160e9 * 2e-6 * 8e-18 / 1e-12;  // 24 E I / L^3
  const auto run = [&](const std::string& name, const std::string& text) {
    WriteFile(dir.path() / name, text);
    return RunJson({(dir.path() / name).string(), "--set", "model.modes=6"});
  };
  const nlohmann::json driven = run("driven.toml", Transient(2e-5, 1e-7));
  ASSERT_EQ(driven["status"], "ok");
  EXPECT_EQ(driven["watched"]["point"], "shuttle");
  EXPECT_EQ(driven["watched"]["component"], "ux");
  std::string loaded = Transient(2e-5, 1e-7);
  const std::size_t comb = loaded.find("[[effects.combs]]");
  char load[120];
  std::snprintf(load, sizeof load,
                "[[loads.points]]\nbody = \"shuttle\"\nforce = [%.17g, 0.0, 0.0]\n", c * 900.0);
  loaded.replace(comb, loaded.find("[analysis]") - comb, load);
  const nlohmann::json pushed = run("loaded.toml", loaded);
  ASSERT_EQ(pushed["status"], "ok");
  const double peak = pushed["displacement_max"].get<double>();
  EXPECT_NEAR(driven["displacement_max"].get<double>(), peak, 1e-12 * peak);

  const nlohmann::json modal =
      RunJson({(dir.path() / "loaded.toml").string(), "--set", "analysis.type=\"modal\""});
  // The shuttle's mode along x (the square beams' out-of-plane mode lies just below it).
  double hz = 0.0, most = 0.0;
  for (const nlohmann::json& mode : modal["modes"]) {
    if (mode["participation"]["ux"].get<double>() > most) {
      most = mode["participation"]["ux"].get<double>();
      hz = mode["frequency_hz"].get<double>();
    }
  }
  char drive[80];
  std::snprintf(drive, sizeof drive, "ac_voltage = 1.0\nfrequency = %.17g\n", hz);
  const nlohmann::json resonant =
      run("resonant.toml",
          Transient(150.0 / hz, 0.01 / hz, drive, "[effects.damping]\nquality_factor = 50.0\n"));
  ASSERT_EQ(resonant["status"], "ok");
  const double offset = c * (900.0 + 0.5) / k, swing = 50.0 * 2.0 * c * 30.0 / k;
  std::printf("resonant comb from the CLI: peak %.6e m against the single mode's %.6e m\n",
              resonant["displacement_max"].get<double>(), offset + swing);
  EXPECT_NEAR(resonant["displacement_max"].get<double>(), offset + swing, 0.04 * swing);
}

// Without electrodes a device's pull-in is its combs' side instability: the voltage the static
// analysis reports (the same closed-form solve), a bifurcation, and the last stable state's
// shuttle at F / k of the voltage there (k = 24 E I / L^3, exact to 1e-10).
TEST(CombDriveCliTest, APullInOfCombsAloneIsTheirSideInstability) {
  const nlohmann::json statics = RunJson({"comb-drive"});
  const nlohmann::json pullin = RunJson({"comb-drive", "--set", "analysis.type=\"pullin\""});
  ASSERT_EQ(pullin["status"], "ok");
  const double side = statics["side_instability_voltage_v"][0].get<double>();
  EXPECT_NEAR(pullin["pullin_voltage_v"].get<double>(), side, 1e-12 * side);
  EXPECT_NEAR(pullin["side_instability_voltage_v"][0].get<double>(), side, 1e-12 * side);
  EXPECT_EQ(pullin["pullin_instability"], "bifurcation");
  EXPECT_EQ(pullin["pullin_point"]["name"], "shuttle");
  const double eps0 = 8.8541878128e-12, k = 2 * 160e9 * 2e-6 * 8e-18 / 1e-12;
  const double engaged = 20 * eps0 * 2e-6 * side * side / 2e-6 / k;
  EXPECT_NEAR(pullin["bodies"]["shuttle"]["displacement"][0].get<double>(), engaged,
              1e-8 * engaged);
  EXPECT_NEAR(pullin["pullin_travel_m"].get<double>(), engaged, 1e-8 * engaged);
  // The comb entries are the static analysis's at the comb's voltage.
  EXPECT_EQ(pullin["combs"][0]["engagement_m"], statics["combs"][0]["engagement_m"]);
  const testing::CliOutcome text =
      testing::Cli({"run", "comb-drive", "--set", "analysis.type=\"pullin\""});
  EXPECT_EQ(text.code, 0);
  ExpectContains(text.out, "the combs' side instability");
  // Above analysis.voltage_max, none: not converged (exit 3), saying why.
  const nlohmann::json bounded = RunJson(
      {"comb-drive", "--set", "analysis.type=\"pullin\"", "--set", "analysis.voltage_max=1000.0"},
      3);
  EXPECT_EQ(bounded["status"], "not converged");
  ExpectContains(bounded["warnings"][0], "no pull-in below analysis.voltage_max = 1000 V");
}

// A comb beside an electrode under the whole device, or beside the Casimir pressure: the
// device's in-plane motion (the comb's) and its motion across the substrate (the pressures')
// are decoupled in the linear theory, so each transducer's result is the one it gives alone, to
// the Newton statics' tolerance (1e-8 asserted): the engagement and side instability of the
// comb alone, the deflection and the pull-in voltage of the electrode with the comb at 0 V.
TEST(CombDriveCliTest, CombsActBesideElectrodesAndSurfaceForces) {
  const TempDirectory dir;
  const std::string driven = (dir.path() / "driven.toml").string();
  const std::string idle = (dir.path() / "idle.toml").string();
  WriteFile(driven, kDrivenFlexure);
  std::string text = kDrivenFlexure;
  text.replace(text.find("voltage = 30.0"), 14, "voltage = 0.0");
  WriteFile(idle, text);
  const std::vector<std::string> electrode = {"--set", "structure.gap=2e-6", "--set",
                                              "effects.electrostatic.voltage=5.0"};
  const auto run = [](const std::string& scene, std::vector<std::string> more) {
    more.insert(more.begin(), scene);
    return RunJson(more);
  };
  const auto near = [](const nlohmann::json& a, const nlohmann::json& b, double tolerance) {
    EXPECT_NEAR(a.get<double>(), b.get<double>(), tolerance * std::abs(b.get<double>()));
  };
  const nlohmann::json comb = run(driven, {});
  const nlohmann::json both = run(driven, electrode);
  const nlohmann::json plate = run(idle, electrode);
  ASSERT_EQ(both["status"], "ok");
  ASSERT_EQ(plate["status"], "ok");
  near(both["combs"][0]["engagement_m"], comb["combs"][0]["engagement_m"], 1e-8);
  near(both["side_instability_voltage_v"][0], comb["side_instability_voltage_v"][0], 1e-8);
  near(both["bodies"]["shuttle"]["displacement"][1], plate["bodies"]["shuttle"]["displacement"][1],
       1e-8);
  EXPECT_LT(both["bodies"]["shuttle"]["displacement"][1].get<double>(), 0.0);
  near(both["capacitance_f"]["electrostatic"], plate["capacitance_f"]["electrostatic"], 1e-8);
  near(both["capacitance_f"]["combs"][0], comb["capacitance_f"]["combs"][0], 1e-8);

  std::vector<std::string> pullin = electrode;
  pullin.insert(pullin.end(), {"--set", "analysis.type=\"pullin\""});
  const nlohmann::json folded = run(driven, pullin);
  const nlohmann::json alone = run(idle, pullin);
  ASSERT_EQ(folded["status"], "ok");
  near(folded["pullin_voltage_v"], alone["pullin_voltage_v"], 1e-8);
  EXPECT_EQ(folded["pullin_instability"], "limit_point");
  near(folded["side_instability_voltage_v"][0], comb["side_instability_voltage_v"][0], 1e-12);

  const nlohmann::json casimir =
      run(driven, {"--set", "structure.gap=0.2e-6", "--set", "effects.casimir.enabled=true"});
  ASSERT_EQ(casimir["status"], "ok");
  near(casimir["combs"][0]["engagement_m"], comb["combs"][0]["engagement_m"], 1e-8);
  near(casimir["side_instability_voltage_v"][0], comb["side_instability_voltage_v"][0], 1e-8);
  EXPECT_LT(casimir["bodies"]["shuttle"]["displacement"][1].get<double>(), 0.0);
}

TEST(CombDriveCliTest, CombsWhereTheyCannotActAreRefused) {
  const TempDirectory dir;
  // The driven flexure with `from` replaced by `to`, run.
  const auto refusal = [&](const std::string& from, const std::string& to) {
    std::string text = kDrivenFlexure;
    text.replace(text.find(from), from.size(), to);
    WriteFile(dir.path() / "variant.toml", text);
    return InvalidInput({"run", (dir.path() / "variant.toml").string()});
  };
  ExpectContains(refusal("body = \"shuttle\"", "body = \"rotor\""),
                 "effects.combs[0].body = \"rotor\": no body \"rotor\"");
  ExpectContains(refusal("voltage = 30.0", "voltage = 30.0\ndirection = [0.0, 1.0, 0.0]"),
                 "effects.combs[0].direction");
  ExpectContains(refusal("fingers = 20", "fingers = 0"), "effects.combs[0].fingers");
  ExpectContains(refusal("type = \"static\"", "type = \"modal\""),
                 "a comb drive acts in the \"static\" and \"pullin\" analyses");
  ExpectContains(refusal("voltage = 30.0", "voltage = 30.0\nac_voltage = 1.0\nfrequency = 1e5"),
                 "effects.combs[0].ac_voltage");
  ExpectContains(refusal("type = \"static\"",
                         "type = \"transient\"\nduration = 1e-5\ntime_step = 1e-7\n"
                         "[[effects.combs]]\nbody = \"shuttle\"\nfingers = 1\ngap = 1e-6\n"
                         "overlap = 1e-6\nvoltage = 1.0\nac_voltage = 1.0"),
                 "effects.combs[1].frequency");
  ExpectContains(
      refusal("kind = \"folded_flexure\"", "kind = \"cantilever\"\nlength = 100e-6\nwidth = 10e-6"),
      "effects.combs");
}

}  // namespace
}  // namespace cosmems
