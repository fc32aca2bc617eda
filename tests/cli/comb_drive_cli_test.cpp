// [[effects.combs]] on a device from the CLI: the folded-flexure resonator driven by a comb on
// its shuttle moves F / k; the capacitance and the side-instability voltage are in the JSON;
// combs where a scene cannot take them are refused naming the key.

#include <gtest/gtest.h>

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
  ExpectContains(
      refusal("kind = \"folded_flexure\"", "kind = \"cantilever\"\nlength = 100e-6\nwidth = 10e-6"),
      "effects.combs");
}

}  // namespace
}  // namespace cosmems
