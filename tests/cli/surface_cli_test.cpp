// Contact, stiction and the surface pressures through the CLI: the release analysis against the
// S-shaped and arc-shaped stuck cantilevers' closed forms, statics that rest on the substrate or
// collapse onto it, a transient touchdown with its events, and the validation of the effects' keys.
// The models' accuracy against independent solutions is held by tests/surface.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "cli_test_support.hpp"
#include "cosmems/scene/scene_loader.hpp"

namespace cosmems {
namespace {

using testing::ExpectContains;
using testing::InvalidInput;
using testing::ReadLines;
using testing::RunJson;
using testing::TempDirectory;

// s^4 = 3 E t^3 g^2 / (2 Gamma) for the scene's beam: 142 um of its 200 um. The edge of contact
// moves node by node (2 um elements): within two of them.
TEST(SurfaceCliTest, StictionSceneStaysStuckWithTheFreeSpanOfTheEnergyBalance) {
  const Scene scene = LoadScene("cantilever-stiction");
  const double span = std::pow(
      3.0 * scene.material.young_modulus * std::pow(scene.structure.thickness, 3) *
          std::pow(*scene.structure.gap, 2) / (2.0 * *scene.effects.stiction->adhesion_energy),
      0.25);
  const nlohmann::json json = RunJson({"cantilever-stiction"});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("analysis"), "release");
  EXPECT_TRUE(json.at("stuck").get<bool>());
  EXPECT_EQ(json.at("shape"), "s");
  const double detached = json.at("detached_length_m").get<double>();
  EXPECT_NEAR(detached, span, 2.0 * scene.structure.length / scene.model.elements);
  EXPECT_NEAR(json.at("contact_length_m").get<double>(), scene.structure.length - detached, 1e-12);
  EXPECT_EQ(json.at("contact").at("state"), "stuck");
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

// Shorter than the S shape's span the beam holds by its tip alone (arc-shaped) down to
// (3 E t^3 g^2 / (8 Gamma))^(1/4) = 100.4 um, and springs free below it.
TEST(SurfaceCliTest, ShorterCantileversStickByTheirTipOrSpringFree) {
  const nlohmann::json arc = RunJson({"cantilever-stiction", "--set", "structure.length=120e-6"});
  EXPECT_EQ(arc.at("status"), "ok");
  EXPECT_TRUE(arc.at("stuck").get<bool>());
  EXPECT_EQ(arc.at("shape"), "arc");
  EXPECT_EQ(arc.at("contact").at("shape"), "arc");
  EXPECT_EQ(arc.at("contact_length_m").get<double>(), 0.0);
  EXPECT_NEAR(arc.at("detached_length_m").get<double>(), 120e-6, 1e-15);
  // de Boer & Michalske's case as the issue put it: E = 164 GPa, t = 2.5 um, 10 um wide over
  // 2 um, L = 140 um between the arc length (117.7 um) and the S span (166.5 um).
  const nlohmann::json example =
      RunJson({"cantilever-stiction", "--set", "material.young_modulus=164e9", "--set",
               "structure.thickness=2.5e-6", "--set", "structure.width=10e-6", "--set",
               "structure.length=140e-6"});
  EXPECT_EQ(example.at("shape"), "arc");
  const nlohmann::json free = RunJson({"cantilever-stiction", "--set", "structure.length=95e-6"});
  EXPECT_EQ(free.at("status"), "ok");
  EXPECT_FALSE(free.at("stuck").get<bool>());
  EXPECT_EQ(free.at("shape"), "free");
  EXPECT_NEAR(free.at("detached_length_m").get<double>(), 95e-6, 1e-15);
}

TEST(SurfaceCliTest, ReleaseWritesTheShapeOnTheSubstrate) {
  const TempDirectory dir;
  RunJson({"cantilever-stiction", "--out", dir.path().string()});
  const std::vector<std::string> lines = ReadLines(dir.path() / "release_shape.csv");
  ASSERT_EQ(lines.size(), 1u + 101u);
  const std::string tip = lines.back();
  const double uy = std::stod(tip.substr(tip.find(',', tip.find(',') + 1) + 1));
  EXPECT_NEAR(uy, -2e-6, 1e-9);  // lying on the substrate, within the contact tolerance
}

// A tip force of three times the one that closes the gap: the tip rests on the substrate.
TEST(SurfaceCliTest, StaticContactStopsTheTipAtTheSubstrate) {
  const nlohmann::json json = RunJson({"cantilever", "--set", "effects.contact={}", "--set",
                                       "loads.tip_force=[0.0, -5.1e-6, 0.0]"});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_NEAR(json.at("tip_displacement")[1].get<double>(), -2e-6, 1e-9);
  EXPECT_FALSE(json.at("collapsed").get<bool>());
  EXPECT_TRUE(json.at("contact").at("in_contact").get<bool>());
  EXPECT_FALSE(json.at("contact").at("stuck").get<bool>());
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

// 20 V is above the cantilever's 14.6 V pull-in: no equilibrium short of the substrate, which
// the result says (exit 3, the pull-in analysis named); with contact the beam lies
// on the contact plane. 10 V holds.
TEST(SurfaceCliTest, StaticAbovePullInCollapses) {
  const std::vector<std::string> pulled = {"cantilever", "--set", "model.dimension=2", "--set",
                                           "effects.electrostatic.voltage=20.0"};
  const nlohmann::json above = RunJson(pulled, 3);
  EXPECT_EQ(above.at("status"), "not converged");
  ExpectContains(above["warnings"].dump(), "pulls in below it");
  std::vector<std::string> floor = pulled;
  floor.insert(floor.end(), {"--set", "effects.contact.separation=1e-7"});
  const nlohmann::json lying = RunJson(floor);
  EXPECT_EQ(lying.at("status"), "ok");
  EXPECT_TRUE(lying.at("collapsed").get<bool>());
  // On the contact plane, within the contact's tolerance (1e-4 of the gap).
  EXPECT_NEAR(lying.at("tip_displacement")[1].get<double>(), -1.9e-6, 1e-4 * 2e-6);
  EXPECT_TRUE(lying.at("contact").at("in_contact").get<bool>());
  const nlohmann::json below = RunJson(
      {"cantilever", "--set", "model.dimension=2", "--set", "effects.electrostatic.voltage=10.0"});
  EXPECT_FALSE(below.at("collapsed").get<bool>());
  EXPECT_LT(below.at("tip_displacement")[1].get<double>(), 0.0);
  EXPECT_EQ(below.at("warnings"), nlohmann::json::array());
}

// What a touchdown run shows: every kind of contact event, and the tip never through the
// substrate in its history.
void ExpectTouchdown(const nlohmann::json& json, const std::vector<std::string>& history) {
  EXPECT_EQ(json.at("status"), "ok");
  const nlohmann::json& events = json.at("contact_events");
  EXPECT_GE(events.at("proximity_warnings").get<int>(), 1);
  EXPECT_GE(events.at("contacts").get<int>(), 1);
  EXPECT_GE(events.at("stuck_events").get<int>(), 1);
  EXPECT_GE(events.at("releases").get<int>(), 1);
  for (const std::string& line : history) {
    if (line.rfind("time_s", 0) == 0) continue;
    EXPECT_GE(std::stod(line.substr(line.find(',') + 1)), -2e-6);
  }
}

TEST(SurfaceCliTest, TouchdownTransientSticksAndIsPulledFree) {
  const TempDirectory dir;
  const nlohmann::json json = RunJson({"cantilever-touchdown", "--out", dir.path().string()});
  ExpectTouchdown(json, ReadLines(dir.path() / "history.csv"));
}

// The first time the tip comes within 5 % of the gap of the substrate [s] in history.csv.
double FirstNearContact(const std::vector<std::string>& lines) {
  for (const std::string& line : lines) {
    if (line.rfind("time_s", 0) == 0) continue;
    if (std::stod(line.substr(line.find(',') + 1)) < -0.95 * 2e-6) return std::stod(line);
  }
  return -1.0;
}

// The air under the beam cushions its fall: the film's force grows like 1/d^3 as the gap d
// closes, so the tip reaches the substrate later, and still sticks.
TEST(SurfaceCliTest, TheSqueezeFilmCushionsTheTouchdown) {
  const TempDirectory bare("_bare"), cushioned("_cushioned");
  RunJson({"cantilever-touchdown", "--out", bare.path().string()});
  const nlohmann::json json =
      RunJson({"cantilever-touchdown", "--set", "effects.squeeze_film.viscosity=1.81e-5", "--out",
               cushioned.path().string()});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_GE(json.at("contact_events").at("stuck_events").get<int>(), 1);
  const double without = FirstNearContact(ReadLines(bare.path() / "history.csv"));
  const double with = FirstNearContact(ReadLines(cushioned.path() / "history.csv"));
  ASSERT_GT(without, 0.0);
  EXPECT_GT(with, without);
}

// The touchdown on the modal path (6 modes, the scene's 0.2 us steps): every kind of event, the tip
// never through the contact plane, and the first approach within 2 % of the time the full model
// takes (measured: the same 0.2 us step; the approach is free motion, which the modes carry).
TEST(SurfaceCliTest, TouchdownOnTheModalPathSticksAndIsPulledFree) {
  const TempDirectory full("_full"), modal("_modal");
  RunJson({"cantilever-touchdown", "--out", full.path().string()});
  // The scene with its integrator swapped (rho_inf belongs to generalised-alpha alone).
  std::string text = testing::Cli({"show", "cantilever-touchdown"}).out;
  const std::pair<std::string, std::string> edits[] = {
      {"integrator = \"generalized-alpha\"", "integrator = \"modal\""},
      {"rho_inf = 0.6", ""},
      {"elements = 20", "elements = 20\nmodes = 6"}};
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  }
  const std::filesystem::path scene = modal.path() / "touchdown-modal.toml";
  testing::WriteFile(scene, text);
  const nlohmann::json json = RunJson({scene.string(), "--out", modal.path().string()});
  EXPECT_EQ(json.at("integrator"), "modal");
  const std::vector<std::string> lines = ReadLines(modal.path() / "history.csv");
  ExpectTouchdown(json, lines);
  const double reference = FirstNearContact(ReadLines(full.path() / "history.csv"));
  ASSERT_GT(reference, 0.0);
  EXPECT_NEAR(FirstNearContact(lines), reference, 0.02 * reference);
}

TEST(SurfaceCliTest, EffectKeysAreValidated) {
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "effects.stiction={}"}),
                 "effects.stiction.adhesion_energy");
  ExpectContains(InvalidInput({"run", "cantilever-modal", "--set", "effects.contact={}"}),
                 "effects.contact");
  ExpectContains(InvalidInput({"run", "cantilever-large-deflection", "--set", "effects.contact={}",
                               "--set", "structure.gap=2e-6"}),
                 "model.theory");
  ExpectContains(InvalidInput({"run", "cantilever-release", "--set", "effects.squeeze_film={}"}),
                 "effects.squeeze_film");
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "effects.electrostatic={}"}),
                 "effects.electrostatic.voltage");
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "analysis.type=release"}),
                 "effects.stiction");
  ExpectContains(InvalidInput({"run", "cantilever-pullin", "--set", "effects.contact={}"}),
                 "effects.contact");
  ExpectContains(
      InvalidInput({"run", "cantilever", "--set", "effects.contact={separation=1.5e-6}"}),
      "effects.contact.separation");
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "effects.contact={bounce=1}"}),
                 "effects.contact.bounce");
}

}  // namespace
}  // namespace cosmems
