// [[effects.combs]] on a device from the CLI: the folded-flexure resonator driven by a comb on
// its shuttle moves F / k; the capacitance and the side-instability voltage are in the JSON;
// combs where a scene cannot take them are refused naming the key.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

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
                 "a comb drive acts in the \"static\" analysis");
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
