#include "run_cli.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test_support.hpp"
#include "cosmems/core/constants.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/scene/embedded_scenes.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "scene/fifo_scene.hpp"
#include "scene/scene_expectations.hpp"

namespace cosmems {
namespace {

using testing::Cli;
using testing::CliOutcome;
using testing::ExpectContains;
using testing::InvalidInput;
using testing::LineCount;
using testing::ReadLines;
using testing::RunJson;
using testing::TempDirectory;

// The static solve reproduces Euler-Bernoulli statics at the nodes to round-off; the margin
// covers the accumulated rounding of a 120-unknown band solve.
constexpr double kStaticTolerance = 1e-9;
// Modal: 20 power-series elements converge f1 far below this; the bound only catches a wrong
// wiring (units, mode order), the core's own tests hold the accuracy.
constexpr double kModalTolerance = 1e-6;

double SecondMoment(const Scene& scene) {
  return scene.structure.width * std::pow(scene.structure.thickness, 3) / 12.0;
}

TEST(RunCliTest, StaticJsonCarriesTheContractFields) {
  const nlohmann::json json = RunJson({"cantilever"});
  EXPECT_EQ(json.at("scene"), "cantilever");
  EXPECT_EQ(json.at("analysis"), "static");
  EXPECT_EQ(json.at("status"), "ok");
  const nlohmann::json& model = json.at("model");
  EXPECT_EQ(model.at("theory"), "linear");
  EXPECT_EQ(model.at("dimension"), 3);
  EXPECT_EQ(model.at("elements"), 20);
  EXPECT_EQ(model.at("series_order"), 1);
  EXPECT_EQ(model.at("modes"), 0);
  EXPECT_EQ(model.at("dofs"), 20 * 6);  // every node but the clamped one, six dofs each
  EXPECT_GT(json.at("wall_time_s").get<double>(), 0.0);
  for (const char* vector : {"tip_displacement", "midspan_displacement", "tip_rotation"}) {
    ASSERT_TRUE(json.at(vector).is_array()) << vector;
    EXPECT_EQ(json.at(vector).size(), 3u) << vector;
  }
  for (const char* number : {"max_deflection", "max_stress_pa", "axial_force_n"}) {
    EXPECT_TRUE(json.at(number).is_number()) << number;
  }
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

TEST(RunCliTest, CantileverTipDeflectionIsPLCubedOverThreeEI) {
  const Scene scene = LoadScene("cantilever");
  const double p = -scene.loads.tip_force.y();
  const double l = scene.structure.length;
  const double ei = scene.material.young_modulus * SecondMoment(scene);
  const double expected_uy = -p * l * l * l / (3.0 * ei);
  const double expected_rz = -p * l * l / (2.0 * ei);
  const nlohmann::json json = RunJson({"cantilever"});
  EXPECT_NEAR(json["tip_displacement"][1].get<double>(), expected_uy,
              kStaticTolerance * std::abs(expected_uy));
  EXPECT_NEAR(json["tip_rotation"][2].get<double>(), expected_rz,
              kStaticTolerance * std::abs(expected_rz));
  EXPECT_NEAR(json["max_deflection"].get<double>(), -expected_uy,
              kStaticTolerance * std::abs(expected_uy));
  // Root stress M c / I with M = P L, c = t / 2.
  const double stress = p * l * 0.5 * scene.structure.thickness / SecondMoment(scene);
  EXPECT_NEAR(json["max_stress_pa"].get<double>(), stress, kStaticTolerance * stress);
  EXPECT_NEAR(json["axial_force_n"].get<double>(), 0.0, 1e-20);
}

TEST(RunCliTest, BridgeReportsMidspanButNoTip) {
  const Scene scene = LoadScene("microbridge");
  const double p = -scene.loads.midspan_force.y();
  const double l = scene.structure.length;
  const double expected_uy =
      -p * l * l * l / (192.0 * scene.material.young_modulus * SecondMoment(scene));
  const nlohmann::json json = RunJson({"microbridge"});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_FALSE(json.contains("tip_displacement"));
  EXPECT_FALSE(json.contains("tip_rotation"));
  EXPECT_NEAR(json["midspan_displacement"][1].get<double>(), expected_uy,
              kStaticTolerance * std::abs(expected_uy));
  EXPECT_EQ(json.at("model").at("dofs"), 19 * 6);
}

// Euler's load of a cantilever, pi^2 EI / (4 L^2); 20 elements are within 2e-7 (h^4).
TEST(RunCliTest, BucklingReportsEulersLoadAndTheModeFile) {
  const Scene scene = LoadScene("cantilever");
  const double l = scene.structure.length;
  const double euler =
      kPi * kPi * scene.material.young_modulus * SecondMoment(scene) / (4.0 * l * l);
  const TempDirectory dir;
  const nlohmann::json json =
      RunJson({"cantilever", "--set", "analysis.type=buckling", "--out", dir.path().string()});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_NEAR(json.at("critical_load_n").get<double>(), euler, 1e-6 * euler);
  EXPECT_NEAR(json.at("critical_stress_pa").get<double>(),
              euler / (scene.structure.width * scene.structure.thickness), 1e-6 * euler / 4e-11);
  ExpectContains(json.at("warnings").dump(), "loads does not change a buckling analysis");
  const std::vector<std::string> lines = ReadLines(dir.path() / "buckling_mode.csv");
  ASSERT_EQ(lines.size(), 1u + 21u);
  EXPECT_EQ(lines[0], "x_m,ux,uy,uz,rx,ry,rz");
}

// Stretching stiffens the pressed bridge (less deflection than the linear beam, tension in the
// axis); a residual tension raises its frequencies.
TEST(RunCliTest, StretchingAndAxialLoadReachTheResults) {
  const std::vector<std::string> hard = {"--set", "loads.midspan_force=[0, -2e-3, 0]", "--set",
                                         "structure.gap=1e-4"};
  std::vector<std::string> linear_args = {"microbridge"};
  linear_args.insert(linear_args.end(), hard.begin(), hard.end());
  std::vector<std::string> stretching_args = linear_args;
  stretching_args.insert(stretching_args.end(), {"--set", "model.theory=stretching"});
  const nlohmann::json linear = RunJson(linear_args);
  const nlohmann::json stretching = RunJson(stretching_args);
  EXPECT_EQ(stretching.at("status"), "ok");
  EXPECT_LT(stretching.at("max_deflection").get<double>(),
            0.8 * linear.at("max_deflection").get<double>());
  EXPECT_GT(stretching.at("axial_force_n").get<double>(), 1e-4);
  EXPECT_EQ(stretching.at("model").at("theory"), "stretching");

  const double f0 = RunJson({"microbridge", "--set", "analysis.type=modal"})
                        .at("frequencies_hz")[0]
                        .get<double>();
  const nlohmann::json tensioned = RunJson(
      {"microbridge", "--set", "analysis.type=modal", "--set", "structure.axial_load=1e-2"});
  EXPECT_GT(tensioned.at("frequencies_hz")[0].get<double>(), 1.2 * f0);
  const nlohmann::json pressed =
      RunJson({"microbridge", "--set", "analysis.type=modal", "--set", "model.theory=stretching",
               "--set", "loads.midspan_force=[0, -2e-3, 0]"});
  EXPECT_GT(pressed.at("frequencies_hz")[0].get<double>(), 1.2 * f0);

  const nlohmann::json transient =
      RunJson({"microbridge", "--set", "analysis.type=transient", "--set", "analysis.duration=2e-6",
               "--set", "analysis.time_step=1e-8", "--set", "model.theory=stretching", "--set",
               "loads.midspan_force=[0, -2e-3, 0]", "--set", "structure.gap=1e-4"});
  EXPECT_EQ(transient.at("status"), "ok");
  EXPECT_EQ(transient.at("steps"), 200);
  // A suddenly applied load overshoots its static deflection, by less than the linear 2x.
  const double peak = transient.at("midspan_displacement_max").get<double>();
  EXPECT_GT(peak, stretching.at("max_deflection").get<double>());
  EXPECT_LT(peak, 2.0 * stretching.at("max_deflection").get<double>());
}

TEST(RunCliTest, PlanarModelHasThreeDofsPerNode) {
  const nlohmann::json json = RunJson({"cantilever", "--set", "model.dimension=2"});
  EXPECT_EQ(json.at("model").at("dimension"), 2);
  EXPECT_EQ(json.at("model").at("dofs"), 20 * 3);
  EXPECT_EQ(json["tip_displacement"][2], 0.0);
}

TEST(RunCliTest, OverridesMayComeBeforeTheScene) {
  const nlohmann::json json =
      RunJson({"--set", "model.elements=4", "cantilever", "--set", "model.series_order=0"});
  EXPECT_EQ(json.at("model").at("elements"), 4);
  EXPECT_EQ(json.at("model").at("series_order"), 0);
}

TEST(RunCliTest, WarnsWhenTheLinearSolutionPassesThroughTheSubstrate) {
  // 100x the tip force: about 12 um of deflection across a 2 um gap.
  const nlohmann::json json = RunJson({"cantilever", "--set", "loads.tip_force=[0, -1e-5, 0]"});
  EXPECT_EQ(json.at("status"), "ok");
  ASSERT_EQ(json.at("warnings").size(), 1u);
  const std::string warning = json["warnings"][0];
  ExpectContains(warning, "passes through the substrate");
  ExpectContains(warning, "declare [effects.contact] to stop it there");
  EXPECT_FALSE(json.at("collapsed").get<bool>());
  EXPECT_FALSE(json.contains("contact"));
}

TEST(RunCliTest, NoWarningWithoutASubstrate) {
  std::string toml(FindEmbeddedScene("cantilever")->toml);
  const std::size_t gap = toml.find("gap = ");
  toml.erase(gap, toml.find('\n', gap) - gap);  // the gap line, comment and all
  const TempDirectory dir;
  const std::string path = (dir.path() / "no_gap.toml").string();
  testing::WriteFile(path, toml);
  const nlohmann::json json = RunJson({path, "--set", "loads.tip_force=[0, -1e-5, 0]"});
  EXPECT_EQ(json.at("scene"), path);
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

TEST(RunCliTest, ModalJsonListsAscendingFrequenciesAndKinds) {
  const Scene scene = LoadScene("cantilever-modal");
  const double l = scene.structure.length;
  const double ei = scene.material.young_modulus * SecondMoment(scene);
  const double rho_a = scene.material.density * scene.structure.width * scene.structure.thickness;
  const double beta1 = 1.87510406871196;  // first root of cos(b) cosh(b) = -1
  const double f1 = beta1 * beta1 / (2.0 * kPi) * std::sqrt(ei / (rho_a * l * l * l * l));

  const nlohmann::json json = RunJson({"cantilever-modal"});
  EXPECT_EQ(json.at("analysis"), "modal");
  EXPECT_EQ(json.at("status"), "ok");
  const nlohmann::json& frequencies = json.at("frequencies_hz");
  const nlohmann::json& modes = json.at("modes");
  ASSERT_EQ(frequencies.size(), 4u);
  ASSERT_EQ(modes.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(modes[i].at("frequency_hz"), frequencies[i]);
    const std::string kind = modes[i].at("kind");
    EXPECT_TRUE(kind == "bending_y" || kind == "bending_z" || kind == "torsion" || kind == "axial")
        << kind;
    if (i > 0) {
      EXPECT_GE(frequencies[i].get<double>(), frequencies[i - 1].get<double>());
    }
  }
  EXPECT_EQ(modes[0].at("kind"), "bending_y");
  EXPECT_NEAR(frequencies[0].get<double>(), f1, kModalTolerance * f1);
}

TEST(RunCliTest, ModalCountComesFromTheScene) {
  const nlohmann::json json = RunJson({"cantilever", "--set", "analysis.type=modal", "--set",
                                       "analysis.count=6", "--set", "model.dimension=2"});
  EXPECT_EQ(json.at("frequencies_hz").size(), 6u);
  for (const nlohmann::json& mode : json.at("modes")) {
    EXPECT_TRUE(mode.at("kind") == "bending_y" || mode.at("kind") == "axial");
  }
}

TEST(RunCliTest, SummaryIsReadable) {
  const CliOutcome outcome = Cli({"run", "cantilever"});
  EXPECT_EQ(outcome.code, 0);
  EXPECT_EQ(outcome.err, "");
  ExpectContains(outcome.out, "cantilever: static analysis");
  ExpectContains(outcome.out, "tip deflection        -1.18");
  ExpectContains(outcome.out, "e-07 m\n");
  ExpectContains(outcome.out, "status     ok");
  ExpectContains(outcome.out, " Pa\n");

  const CliOutcome modal = Cli({"run", "cantilever-modal"});
  EXPECT_EQ(modal.code, 0);
  ExpectContains(modal.out, "kHz   bending_y");
  EXPECT_EQ(LineCount(modal.out.substr(modal.out.find("mode   frequency"))), 5);
}

TEST(RunCliTest, SummaryShowsWarnings) {
  const CliOutcome outcome = Cli({"run", "cantilever", "--set", "loads.tip_force=[0, -1e-5, 0]"});
  EXPECT_EQ(outcome.code, 0);
  ExpectContains(outcome.out, "warning: the linear solution deflects");
}

TEST(RunCliTest, StaticOutWritesTheDeflectionTable) {
  const TempDirectory dir;
  const std::filesystem::path out = dir.path() / "nested" / "results";
  const nlohmann::json json = RunJson({"cantilever", "--out", out.string()});
  const std::vector<std::string> lines = ReadLines(out / "deflection.csv");
  ASSERT_EQ(lines.size(), 1u + 21u);  // header, one row per node
  EXPECT_EQ(lines[0], "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  EXPECT_EQ(lines[1], "0,0,0,0,0,0,0");
  std::istringstream last(lines.back());
  std::vector<double> cells;
  for (std::string cell; std::getline(last, cell, ',');) cells.push_back(std::stod(cell));
  ASSERT_EQ(cells.size(), 7u);
  EXPECT_DOUBLE_EQ(cells[0], 200e-6);
  EXPECT_DOUBLE_EQ(cells[2], json["tip_displacement"][1].get<double>());
  EXPECT_DOUBLE_EQ(cells[6], json["tip_rotation"][2].get<double>());
}

TEST(RunCliTest, ModalOutWritesModesAndNormalisedShapes) {
  const TempDirectory dir;
  const CliOutcome outcome = Cli({"run", "cantilever-modal", "--out", dir.path().string()});
  EXPECT_EQ(outcome.code, 0) << outcome.err;
  ExpectContains(outcome.out, "files written to " + dir.path().string());

  const std::vector<std::string> modes = ReadLines(dir.path() / "modes.csv");
  ASSERT_EQ(modes.size(), 1u + 4u);
  EXPECT_EQ(modes[0], "mode,frequency_hz,kind,ux,uy,uz,rx,ry,rz");
  EXPECT_EQ(modes[1].rfind("1,", 0), 0u);
  EXPECT_NE(modes[1].find(",bending_y"), std::string::npos);

  const std::vector<std::string> shapes = ReadLines(dir.path() / "mode_shapes.csv");
  ASSERT_EQ(shapes.size(), 1u + 4u * 21u);
  EXPECT_EQ(shapes[0], "mode,x_m,ux,uy,uz,rx,ry,rz");
  std::vector<double> largest(4, 0.0);
  for (std::size_t row = 1; row < shapes.size(); ++row) {
    std::istringstream line(shapes[row]);
    std::vector<double> cells;
    for (std::string cell; std::getline(line, cell, ',');) cells.push_back(std::stod(cell));
    ASSERT_EQ(cells.size(), 8u);
    const int mode = static_cast<int>(cells[0]);
    ASSERT_TRUE(mode >= 1 && mode <= 4);
    for (int c = 2; c <= 4; ++c) {
      largest[mode - 1] = std::max(largest[mode - 1], std::abs(cells[c]));
    }
  }
  for (std::size_t i = 0; i < 4; ++i) {
    if (modes[i + 1].find(",torsion") == std::string::npos) {
      EXPECT_DOUBLE_EQ(largest[i], 1.0) << "mode " << i + 1;
    }
  }
}

// A pull-in search bounded below the pull-in voltage finds no fold: a numerical status. (The
// absurd modulus of 1e-300 Pa that once overflowed the deflection is invalid input now.)
const std::vector<std::string> kUnconvergedScene = {"cantilever-pullin", "--set",
                                                    "analysis.voltage_max=10.0"};

TEST(RunCliTest, NumericalFailureStillPrintsTheJsonAndExitsThree) {
  const TempDirectory dir;
  std::vector<std::string> args = kUnconvergedScene;
  args.insert(args.end(), {"--out", (dir.path() / "results").string()});
  const nlohmann::json json = RunJson(args, 3);
  EXPECT_EQ(json.at("status"), ToString(Status::kNotConverged));
  EXPECT_EQ(json.at("model").at("dofs"), 60);  // planar: 20 nodes, three dofs each
  EXPECT_TRUE(json.contains("wall_time_s"));
  EXPECT_FALSE(json.contains("pullin_voltage_v"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "results" / "pullin_shape.csv"));
}

TEST(RunCliTest, NumericalFailureSummarySaysWhy) {
  std::vector<std::string> args = kUnconvergedScene;
  args.insert(args.begin(), "run");
  const CliOutcome outcome = Cli(args);
  EXPECT_EQ(outcome.code, 3);
  EXPECT_EQ(outcome.err, "");
  ExpectContains(outcome.out, std::string("status     ") + ToString(Status::kNotConverged));
  EXPECT_EQ(outcome.out.find("pull-in voltage"), std::string::npos);
}

TEST(RunCliTest, ScenesListsEachEmbeddedSceneOnOneLine) {
  const CliOutcome outcome = Cli({"scenes"});
  EXPECT_EQ(outcome.code, 0);
  EXPECT_EQ(LineCount(outcome.out), static_cast<long>(EmbeddedScenes().size()));
  for (const EmbeddedScene& scene : EmbeddedScenes()) {
    ExpectContains(outcome.out, std::string(scene.name));
    ExpectContains(outcome.out, std::string(scene.description) + "\n");
  }
  EXPECT_EQ(outcome.out.rfind("accelerometer ", 0), 0u);  // in name order
  ExpectContains(outcome.out, "\ncantilever ");
  ExpectContains(outcome.out, "\nmicrobridge ");
}

TEST(RunCliTest, ShowPrintsAFileThatLoadsToTheSameScene) {
  for (const char* name : {"cantilever", "microbridge", "cantilever-modal", "cantilever-release"}) {
    SCOPED_TRACE(name);
    const CliOutcome outcome = Cli({"show", name});
    EXPECT_EQ(outcome.code, 0);
    EXPECT_EQ(outcome.out, FindEmbeddedScene(name)->toml);
    const TempDirectory dir;
    const std::filesystem::path path = dir.path() / "copy.toml";
    testing::WriteFile(path, outcome.out);
    testing::ExpectSameScene(LoadSceneFile(path.string()), LoadScene(name));
  }
}

TEST(RunCliTest, HelpAndVersion) {
  const CliOutcome help = Cli({"--help"});
  EXPECT_EQ(help.code, 0);
  for (const char* command : {"run", "scenes", "show", "--version"})
    ExpectContains(help.out, command);
  const CliOutcome run_help = Cli({"run", "--help"});
  EXPECT_EQ(run_help.code, 0);
  for (const char* option : {"SCENE", "--set", "KEY=VALUE", "--json", "--out"}) {
    ExpectContains(run_help.out, option);
  }
  const CliOutcome version = Cli({"--version"});
  EXPECT_EQ(version.code, 0);
  EXPECT_EQ(version.out, std::string("cosmems ") + COSMEMS_VERSION + "\n");
}

TEST(RunCliTest, SceneErrorsAreOneLineWithExitTwo) {
  EXPECT_EQ(InvalidInput({"run", "cantilever", "--set", "model.elements=0"}),
            "cosmems: --set: model.elements = 0: must be at least 1\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever", "--json", "--set", "model.theory=stretching"}),
            "cosmems: --set: model.theory = \"stretching\": \"stretching\" needs both ends held "
            "axially: structure.kind = \"bridge\", or a device\n");
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "structure.lenght=1e-4"}),
                 "structure.lenght = 1e-04: unknown key");
  ExpectContains(InvalidInput({"run", "cantilever-haptic", "--set", "analysis.rate=750"}),
                 "analysis.rate = 750: must be 500, 1000 or 2000");
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "model.elements"}),
                 "expected KEY=VALUE");
  ExpectContains(InvalidInput({"run", "no-such-scene"}),
                 "no-such-scene: neither an embedded scene");
  ExpectContains(InvalidInput({"run", "missing.toml"}), "missing.toml: cannot open scene file");
  ExpectContains(InvalidInput({"show", "no-such-scene"}), "no-such-scene: not an embedded scene");
}

TEST(RunCliTest, BadFilesAreOneLineWithExitTwo) {
  const TempDirectory dir;
  const std::string broken = (dir.path() / "broken.toml").string();
  testing::WriteFile(broken, "[structure\nlength = 1\n");
  ExpectContains(InvalidInput({"run", broken}), broken + ": invalid TOML at line 1");
  const std::string wrong = (dir.path() / "wrong.toml").string();
  std::string text(FindEmbeddedScene("cantilever")->toml);
  text.replace(text.find("length = 200e-6"), 15, "length = -2e-6");
  testing::WriteFile(wrong, text);
  EXPECT_EQ(InvalidInput({"run", wrong}),
            "cosmems: " + wrong + ": structure.length = -2e-06: must be positive\n");
}

// What the model cannot represent is invalid input, named with its bound, through --set as in a
// file.
TEST(RunCliTest, ValuesBeyondTheirBoundsAreOneLineWithExitTwo) {
  EXPECT_EQ(InvalidInput({"run", "cantilever", "--set", "material.young_modulus=1e-300"}),
            "cosmems: --set: material.young_modulus = 1e-300: must lie in [1, 1e+13] Pa\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever", "--set", "structure.thickness=1e-120"}),
            "cosmems: --set: structure.thickness = 1e-120: must lie in [1e-12, 1] m\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever-modal", "--set", "analysis.count=2000000000"}),
            "cosmems: --set: analysis.count = 2000000000: must be at most 100\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever-haptic", "--set", "analysis.duration=1e5"}),
            "cosmems: --set: analysis.duration = 1e+05: must lie in [1e-15, 3600] s\n");
  const TempDirectory dir;
  const std::string thin = (dir.path() / "thin.toml").string();
  std::string text(FindEmbeddedScene("cantilever")->toml);
  text.replace(text.find("thickness = 2e-6"), 16, "thickness = 1e-120");
  testing::WriteFile(thin, text);
  EXPECT_EQ(InvalidInput({"run", thin}),
            "cosmems: " + thin + ": structure.thickness = 1e-120: must lie in [1e-12, 1] m\n");
}

// Only a regular file of at most 1 MiB is read as a scene: a device or a FIFO could be read
// without end, and anything larger is not a scene.
TEST(RunCliTest, WhatIsNotASceneFileIsOneLineWithExitTwo) {
  const std::string not_regular =
      ": not a regular file (a FIFO, socket or device), not a scene file\n";
  EXPECT_EQ(InvalidInput({"run", "/dev/zero"}), "cosmems: /dev/zero" + not_regular);
  const TempDirectory dir;
  const std::string scene(FindEmbeddedScene("cantilever")->toml);
  const testing::FifoScene fifo(dir.path() / "fifo.toml", scene);
  EXPECT_EQ(InvalidInput({"run", fifo.path(), "--json"}), "cosmems: " + fifo.path() + not_regular);
  const std::string large = (dir.path() / "large.toml").string();
  testing::WriteFile(large, scene + "#" + std::string(std::size_t{1} << 20, 'x') + "\n");
  EXPECT_EQ(InvalidInput({"run", large}),
            "cosmems: " + large +
                ": larger than 1048576 bytes (1 MiB), the most a scene file may hold\n");
}

// Settings the analysis accepts but does not use are named in the warnings: the haptic analysis
// presses the beam with the probe alone (the forces it sends are the same without them), and
// only the haptic analysis has a stylus.
TEST(RunCliTest, WarnsAboutSettingsTheHapticAnalysisIgnoresAndAStylusElsewhere) {
  const std::vector<std::string> fast = {"cantilever-haptic", "--set", "device.realtime=false",
                                         "--set", "analysis.duration=0.2"};
  std::vector<std::string> args = fast;
  args.insert(args.end(), {"--set", "loads.tip_force=[0, -1e-7, 0]", "--set",
                           "effects.damping.quality_factor=100.0", "--set",
                           "loads.time_function=ramp", "--set", "loads.ramp_time=1e-3"});
  const nlohmann::json with = RunJson(args);
  const nlohmann::json without = RunJson(fast);
  EXPECT_EQ(without.at("warnings"), nlohmann::json::array());
  EXPECT_EQ(with.at("max_device_force_n"), without.at("max_device_force_n"));
  EXPECT_EQ(with.at("contact_events"), without.at("contact_events"));
  const nlohmann::json& warnings = with.at("warnings");
  ASSERT_EQ(warnings.size(), 3u) << warnings;
  EXPECT_EQ(warnings[0],
            "loads does not change a haptic analysis: the hand's probe is the only load on the "
            "structure");
  ExpectContains(warnings[1], "effects.damping does not change a haptic analysis: ");
  EXPECT_EQ(warnings[2],
            "loads.time_function = \"ramp\" does not change a haptic analysis: it sets how the "
            "loads vary in transient analyses only");

  const nlohmann::json static_run = RunJson({"cantilever-haptic", "--set", "analysis.type=static"});
  EXPECT_EQ(static_run.at("warnings"),
            nlohmann::json::array({"device does not change a static analysis: [device] is the "
                                   "stylus of a haptic analysis only"}));
}

TEST(RunCliTest, UsageErrorsAreOneLineWithExitTwo) {
  ExpectContains(InvalidInput({}), "subcommand");
  ExpectContains(InvalidInput({"run"}), "SCENE");
  ExpectContains(InvalidInput({"run", "cantilever", "--bogus"}), "--bogus");
  ExpectContains(InvalidInput({"run", "cantilever", "--set"}), "--set");
  ExpectContains(InvalidInput({"run", "cantilever", "--out", ""}), "DIR must not be empty");
  EXPECT_EQ(InvalidInput({"frobnicate"}),
            "cosmems: unknown command \"frobnicate\" (expected run, netlist, sweep, scenes, show, "
            "keys)\n");
}

// Text a terminal would act on: every C0 control but the closing line feed, DEL, and the C1
// controls (UTF-8 C2 80 ... C2 9F; C2 9B starts an escape sequence on some terminals).
void ExpectPrintable(const std::string& text) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const bool closing = i + 1 == text.size() && c == '\n';
    EXPECT_TRUE(closing || (c >= 0x20 && c != 0x7F)) << "byte " << i << " of: " << text;
    if (c == 0xC2 && i + 1 < text.size()) {
      EXPECT_GE(static_cast<unsigned char>(text[i + 1]), 0xA0) << "byte " << i << " of: " << text;
    }
  }
}

// A --set value, a file name, a command or an option that holds control characters (a title
// sequence, a screen clear) is echoed escaped, so that the message cannot retitle or garble the
// terminal: \n, \r and \t by name, other controls and invalid UTF-8 byte by byte as \xNN.
TEST(RunCliTest, EchoedTextIsEscapedNotSentToTheTerminal) {
  std::string err =
      InvalidInput({"run", "cantilever", "--set", "structure.length=\x1b]0;owned\x07"});
  ExpectPrintable(err);
  ExpectContains(err, "--set: structure.length = \\x1B]0;owned\\x07: not a TOML value");
  const std::string csi = "\xc2\x9b";  // U+009B, the C1 control sequence introducer
  err = InvalidInput({"run", "cantilever", "--set", "device.trajectory=a\tb" + csi + "2J\xff"});
  ExpectPrintable(err);
  ExpectContains(err, "device.trajectory = a\\tb\\xC2\\x9B2J\\xFF: not a TOML value");
  err = InvalidInput({"run", "no\x1b[2Jscene.toml"});
  ExpectPrintable(err);
  ExpectContains(err, "cosmems: no\\x1B[2Jscene.toml: cannot open scene file");
  err = InvalidInput({"show", "\x1b[31mred"});
  ExpectPrintable(err);
  ExpectContains(err, "cosmems: \\x1B[31mred: not an embedded scene");
  err = InvalidInput({"ru\x1bn"});
  ExpectPrintable(err);
  ExpectContains(err, "unknown command \"ru\\x1Bn\"");
  err = InvalidInput({"run", "cantilever", "--bo\rgus"});
  ExpectPrintable(err);
  ExpectContains(err, "--bo\\rgus");
  // Printable UTF-8 passes unchanged.
  ExpectContains(InvalidInput({"run", "d\xc3\xa9j\xc3\xa0.toml"}),
                 "d\xc3\xa9j\xc3\xa0.toml: cannot open");
}

TEST(RunCliTest, UnwritableOutIsInvalidInput) {
  const TempDirectory dir;
  const std::filesystem::path file = dir.path() / "a_file";
  testing::WriteFile(file, "");
  ExpectContains(InvalidInput({"run", "cantilever", "--json", "--out", file.string()}),
                 "--out " + file.string() + ": cannot create the directory");
}

}  // namespace
}  // namespace cosmems
