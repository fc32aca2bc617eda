// `cosmems run` on transient scenes: the contract's JSON fields and history.csv, checked against
// the closed forms of a released, damped Euler-Bernoulli cantilever and a suddenly loaded bridge.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_test_support.hpp"
#include "cosmems/core/constants.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using testing::Cli;
using testing::CliOutcome;
using testing::ExpectContains;
using testing::InvalidInput;
using testing::ReadLines;
using testing::RunJson;
using testing::TempDirectory;

// A history.csv: its header and the two columns.
struct History {
  std::string header;
  std::vector<double> time_s;
  std::vector<double> uy_m;
};

History ReadHistory(const std::filesystem::path& path) {
  const std::vector<std::string> lines = ReadLines(path);
  History history;
  if (lines.empty()) return history;
  history.header = lines[0];
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::istringstream row(lines[i]);
    std::string time, uy;
    std::getline(row, time, ',');
    std::getline(row, uy);
    history.time_s.push_back(std::stod(time));
    history.uy_m.push_back(std::stod(uy));
  }
  return history;
}

// The reference cantilever's flexural rigidity EI [N m^2] and mass per length rho A [kg/m].
struct Beam {
  double length, ei, rho_a, force;
};

Beam ReleaseBeam() {
  const Scene scene = LoadScene("cantilever-release");
  const double w = scene.structure.width;
  const double t = scene.structure.thickness;
  return {scene.structure.length, scene.material.young_modulus * w * t * t * t / 12.0,
          scene.material.density * w * t, -scene.loads.tip_force.y()};
}

// -P L^3 / (3 EI): the tip's static deflection under the scene's tip force.
double StaticTip(const Beam& b) { return -b.force * std::pow(b.length, 3) / (3.0 * b.ei); }

// The first natural frequency of the Euler-Bernoulli cantilever [Hz].
double FirstFrequency(const Beam& b) {
  return test::BendingFrequency(test::FrequencyRoot(1, -1), b.length, b.ei, b.rho_a);
}

constexpr double kQualityFactor = 100.0;  // cantilever-release's effects.damping

const std::vector<std::string> kNewmarkRelease = {
    "cantilever-release",    "--set", "analysis.integrator=newmark", "--set",
    "model.modes=0",         "--set", "analysis.time_step=1e-7",     "--set",
    "analysis.duration=1e-4"};

TEST(TransientCliTest, ReleaseJsonCarriesTheContractFields) {
  const nlohmann::json json = RunJson({"cantilever-release"});
  EXPECT_EQ(json.at("scene"), "cantilever-release");
  EXPECT_EQ(json.at("analysis"), "transient");
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("model").at("dimension"), 2);
  EXPECT_EQ(json.at("model").at("modes"), 4);
  EXPECT_EQ(json.at("model").at("dofs"), 20 * 3);
  EXPECT_EQ(json.at("steps"), 1000);
  const nlohmann::json& step = json.at("step_time_us");
  EXPECT_GT(step.at("median").get<double>(), 0.0);
  EXPECT_GE(step.at("p99").get<double>(), step.at("median").get<double>());
  EXPECT_GE(step.at("max").get<double>(), step.at("p99").get<double>());
  const double wall = json.at("wall_time_s");
  EXPECT_GT(wall, 0.0);
  EXPECT_DOUBLE_EQ(json.at("realtime_factor").get<double>(), 1e-3 / wall);
  // The steps alone take part of the wall time, so they run at least as fast as the whole.
  EXPECT_GE(json.at("stepping_realtime_factor").get<double>(),
            json.at("realtime_factor").get<double>());
  EXPECT_GT(json.at("tip_displacement_max").get<double>(), 0.0);
  EXPECT_FALSE(json.contains("midspan_displacement_max"));
  EXPECT_DOUBLE_EQ(json.at("simulated_time_s").get<double>(), 1e-3);
  EXPECT_EQ(json.at("integrator"), "modal");
  EXPECT_EQ(json.at("time_step_s"), 1e-6);
  EXPECT_EQ(json.at("warnings"), nlohmann::json::array());
}

// At t = 0 the modal path holds the projection of the static deflection d0 on its 4 modes (the
// loads are gone, so the static correction for the truncated modes is zero). For a tip force
// the Euler-Bernoulli expansion gives the tip's share of mode i as 12 / beta_i^4, beta_i the
// roots of cos b cosh b = -1: the 4 modes hold 1 - 6.2e-4 of -P L^3 / (3 EI).
TEST(TransientCliTest, ReleaseStartsAtTheFourModeProjectionOfTheStaticDeflection) {
  const TempDirectory dir;
  const nlohmann::json json = RunJson({"cantilever-release", "--out", dir.path().string()});
  const History history = ReadHistory(dir.path() / "history.csv");
  EXPECT_EQ(history.header, "time_s,tip_uy_m");
  ASSERT_EQ(history.time_s.size(), 1001u);  // t = 0 and every step
  EXPECT_EQ(history.time_s[0], 0.0);
  EXPECT_EQ(history.time_s[3], 3e-6);  // written rounded, not as 3 * 1e-6
  EXPECT_EQ(history.time_s.back(), 1e-3);

  double share = 0.0;
  for (int i = 1; i <= 4; ++i) share += 12.0 / std::pow(test::FrequencyRoot(i, -1), 4);
  const double statics = StaticTip(ReleaseBeam());
  // Measured 1.2e-7: 20 power-series elements resolve modes 1-4 to 1e-8 (their frequencies)
  // and somewhat less in shape; 1e-6 leaves room for that and none for a lost mode (2.5e-2,
  // 3.2e-3, 8.2e-4 for modes 2-4) or a missing mass term.
  EXPECT_NEAR(history.uy_m[0], share * statics, 1e-6 * std::abs(statics));
  // Against the full static deflection, the modes from the fifth on are missing:
  // 12 sum_(i>4) beta_i^-4 = 6.2e-4.
  EXPECT_NEAR(history.uy_m[0] / statics, 1.0, 1e-3);
  // A release of positive modal contributions never passes its start.
  EXPECT_DOUBLE_EQ(json.at("tip_displacement_max").get<double>(), -history.uy_m[0]);
}

// Q = 100 damps every mode at zeta = 1 / (2 Q): successive troughs of the tip shrink by
// exp(-2 pi zeta / sqrt(1 - zeta^2)) ~ exp(-pi / Q). The modal path is exact at any step, so a
// step of 10 ns only samples the same motion finely (every 50 ns in the history's 20000 rows).
TEST(TransientCliTest, ReleaseRingsDownAtTheQualityFactor) {
  const TempDirectory dir;
  RunJson({"cantilever-release", "--set", "analysis.time_step=1e-8", "--out", dir.path().string()});
  const History history = ReadHistory(dir.path() / "history.csv");
  ASSERT_GT(history.time_s.size(), 20000u);
  const double zeta = 0.5 / kQualityFactor;
  const double damped_period = 1.0 / (FirstFrequency(ReleaseBeam()) * std::sqrt(1 - zeta * zeta));
  const double expected = std::exp(-2.0 * kPi * zeta / std::sqrt(1.0 - zeta * zeta));

  // The lowest sample within half a period of each trough k T_d. Only troughs from 0.5 ms on:
  // modes 2-4 (2.9 % of the start) decay 6-32 times faster than mode 1 and shift the early
  // troughs by up to 2.5 %, but are below 1e-4 of mode 1 by then.
  std::vector<double> troughs;
  std::size_t i = 0;
  for (int k = 1; (k + 0.5) * damped_period <= history.time_s.back(); ++k) {
    while (history.time_s[i] < (k - 0.5) * damped_period) ++i;
    double lowest = history.uy_m[i];
    for (; history.time_s[i] < (k + 0.5) * damped_period; ++i) {
      lowest = std::min(lowest, history.uy_m[i]);
    }
    if (k * damped_period >= 0.5e-3) troughs.push_back(lowest);
  }
  ASSERT_GE(troughs.size(), 30u);
  // Samples 1/290 of a period apart find a trough within (pi / 290)^2 / 2 = 5.9e-5 of itself,
  // and the higher modes add < 1e-4: 5e-4 covers both (measured 8e-5).
  for (std::size_t k = 1; k < troughs.size(); ++k) {
    EXPECT_NEAR(troughs[k] / troughs[k - 1], expected, 5e-4) << "trough " << k;
  }
  EXPECT_NEAR(expected, std::exp(-kPi / kQualityFactor), 1e-6);
}

// The full model by average acceleration at 100 steps per microsecond: it starts from the
// whole static deflection, the modal run from its 4-mode projection (6.2e-4 less), and both
// then follow the same motion.
TEST(TransientCliTest, NewmarkAgreesWithTheModalRelease) {
  const TempDirectory dir;  // one per test: its name is the test's
  const std::filesystem::path modal_dir = dir.path() / "modal";
  const std::filesystem::path newmark_dir = dir.path() / "newmark";
  const nlohmann::json modal = RunJson({"cantilever-release", "--out", modal_dir.string()});
  std::vector<std::string> args = kNewmarkRelease;
  args.insert(args.end(), {"--out", newmark_dir.string()});
  const nlohmann::json newmark = RunJson(args);
  EXPECT_EQ(newmark.at("integrator"), "newmark");
  EXPECT_EQ(newmark.at("steps"), 1000);
  EXPECT_EQ(newmark.at("model").at("modes"), 0);
  const double modal_peak = modal.at("tip_displacement_max");
  const double newmark_peak = newmark.at("tip_displacement_max");
  EXPECT_NEAR(newmark_peak, modal_peak, 0.01 * modal_peak);
  const double statics = std::abs(StaticTip(ReleaseBeam()));
  EXPECT_NEAR(newmark_peak, statics, 1e-9 * statics);  // the full static deflection, at t = 0

  // At the modal run's samples (every 1 us) over the first 0.1 ms. Average acceleration at
  // 1e-7 s lengthens mode 1's period by (w dt)^2 / 12 = 1.6e-4 (0.7 % of phase after 7
  // periods) and mode 2's by 0.6 %, which turns its 2.5 % share out of phase; Q = 100 becomes
  // Rayleigh damping exact at modes 1 and 2 only. Measured 1.4 % of the static deflection.
  const History a = ReadHistory(modal_dir / "history.csv");
  const History b = ReadHistory(newmark_dir / "history.csv");
  ASSERT_EQ(b.time_s.size(), 1001u);
  int compared = 0;
  for (std::size_t k = 0; k < b.time_s.size(); k += 10) {
    const auto m = static_cast<std::size_t>(std::lround(b.time_s[k] / 1e-6));
    ASSERT_DOUBLE_EQ(a.time_s[m], b.time_s[k]);
    EXPECT_NEAR(b.uy_m[k], a.uy_m[m], 0.02 * statics) << "t = " << b.time_s[k];
    ++compared;
  }
  EXPECT_EQ(compared, 101);
}

// A tip force ramped up over 150 us, ten periods of mode 1, barely excites the beam: the tip
// creeps to its static deflection and overshoots it by at most 2 / (w1 T_ramp) (the undamped
// bound for a ramp), 3.1 % here.
TEST(TransientCliTest, SlowRampFromRestReachesTheStaticDeflection) {
  const Beam beam = ReleaseBeam();
  const double ramp_time = 150e-6;
  const nlohmann::json json =
      RunJson({"cantilever-release", "--set", "analysis.initial=rest", "--set",
               "loads.time_function=ramp", "--set", "loads.ramp_time=150e-6"});
  const double peak = json.at("tip_displacement_max");
  const double statics = std::abs(StaticTip(beam));
  // The modal path's static correction gives the truncated modes' share too: once the load is
  // on, the tip oscillates about the whole static deflection (measured peak: 1.021 of it).
  EXPECT_GT(peak, statics);
  EXPECT_LT(peak, statics * (1.0 + 2.0 / (2.0 * kPi * FirstFrequency(beam) * ramp_time)));
}

// A suddenly applied midspan force on the bridge, undamped: every mode overshoots to twice its
// static share, so the midspan peaks just under twice P L^3 / (192 EI). History and JSON name
// the midspan (an extension of the contract, which names only the tip).
TEST(TransientCliTest, BridgeTransientRecordsTheMidspan) {
  const Scene scene = LoadScene("microbridge");
  const double w = scene.structure.width;
  const double t = scene.structure.thickness;
  const double ei = scene.material.young_modulus * w * t * t * t / 12.0;
  const double statics =
      -scene.loads.midspan_force.y() * std::pow(scene.structure.length, 3) / (192.0 * ei);
  const TempDirectory dir;
  const nlohmann::json json =
      RunJson({"microbridge", "--set", "analysis.type=transient", "--set", "analysis.duration=2e-6",
               "--set", "analysis.time_step=2e-9", "--out", dir.path().string()});
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("integrator"), "newmark");
  EXPECT_FALSE(json.contains("tip_displacement_max"));
  const double peak = json.at("midspan_displacement_max");
  EXPECT_GT(peak, 1.9 * statics);
  EXPECT_LT(peak, 2.0 * statics * (1 + 1e-6));
  const History history = ReadHistory(dir.path() / "history.csv");
  EXPECT_EQ(history.header, "time_s,midspan_uy_m");
  ASSERT_EQ(history.time_s.size(), 1001u);
  EXPECT_EQ(history.uy_m[0], 0.0);  // from rest
}

TEST(TransientCliTest, SummaryIsReadable) {
  const CliOutcome outcome = Cli({"run", "cantilever-release"});
  EXPECT_EQ(outcome.code, 0);
  EXPECT_EQ(outcome.err, "");
  ExpectContains(outcome.out, "cantilever-release: transient analysis, linear theory\n");
  ExpectContains(outcome.out, "integrator            modal, 4 modes, released from the static");
  ExpectContains(outcome.out, "time step             1e-06 s\n");
  ExpectContains(outcome.out, "steps                 1000 (0.001 s simulated)\n");
  ExpectContains(outcome.out, "step time             median ");
  ExpectContains(outcome.out, " us, p99 ");
  ExpectContains(outcome.out, "realtime factor       ");
  ExpectContains(outcome.out, "max |uy| at tip       1.18");
}

// 1 us is far above the explicit rule's stability limit of this mesh (2 / w_max ~ 0.7 ns, set
// by the axial modes): the solution grows until it overflows, and the run says so.
TEST(TransientCliTest, UnstableCentralDifferenceExitsThreeWithTheJson) {
  const TempDirectory dir;
  const nlohmann::json json =
      RunJson({"cantilever-release", "--set", "analysis.integrator=central-difference", "--set",
               "model.modes=0", "--out", (dir.path() / "results").string()},
              3);
  // 1 us is 1500 times central difference's limit here: caught as diverged long before the
  // motion could overflow.
  EXPECT_EQ(json.at("status"), ToString(Status::kDiverged));
  EXPECT_EQ(json.at("analysis"), "transient");
  EXPECT_FALSE(json.contains("steps"));
  EXPECT_FALSE(json.contains("tip_displacement_max"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "results" / "history.csv"));
}

TEST(TransientCliTest, WarnsWhenTheTipPassesThroughTheSubstrate) {
  // 100x the force: 12 um of static deflection across a 2 um gap.
  const nlohmann::json json =
      RunJson({"cantilever-release", "--set", "loads.tip_force=[0, -1e-5, 0]"});
  ASSERT_EQ(json.at("warnings").size(), 1u);
  const std::string warning = json["warnings"][0];
  ExpectContains(warning, "the tip moves 1.18");
  ExpectContains(warning, "toward the substrate, at least the gap of 2e-06 m");
  ExpectContains(warning, "declare [effects.contact] to stop it there");
}

TEST(TransientCliTest, WarnsWhenThereIsNothingToMoveTheBeam) {
  const nlohmann::json json = RunJson({"cantilever-release", "--set", "loads.tip_force=[0, 0, 0]"});
  EXPECT_EQ(json.at("tip_displacement_max"), 0.0);
  ASSERT_EQ(json.at("warnings").size(), 1u);
  EXPECT_EQ(json["warnings"][0], "the loads are all zero: the beam stays at rest");
}

TEST(TransientCliTest, WarnsWhenMoreModesAreAskedForThanTheModelHas) {
  const nlohmann::json json = RunJson({"cantilever-release", "--set", "model.elements=1", "--set",
                                       "model.series_order=0", "--set", "model.modes=5"});
  EXPECT_EQ(json.at("status"), "ok");
  ASSERT_EQ(json.at("warnings").size(), 1u);
  EXPECT_EQ(json["warnings"][0], "model.modes = 5 modes asked for, but the model has only 3");
}

// Damping, modal reduction and load time functions act in transient analyses only: a static or
// modal run accepts them, says so, and gives the result it gives without them.
TEST(TransientCliTest, StaticAndModalRunsWarnAboutTransientOnlySettings) {
  const std::vector<std::string> settings = {"--set", "effects.damping.quality_factor=100.0",
                                             "--set", "model.modes=4",
                                             "--set", "loads.time_function=ramp",
                                             "--set", "loads.ramp_time=1e-5"};
  std::vector<std::string> args = {"cantilever"};
  args.insert(args.end(), settings.begin(), settings.end());
  const nlohmann::json with = RunJson(args);
  const nlohmann::json without = RunJson({"cantilever"});
  EXPECT_EQ(with.at("tip_displacement"), without.at("tip_displacement"));
  const nlohmann::json& warnings = with.at("warnings");
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0],
            "effects.damping does not change a static analysis: damping acts in transient "
            "analyses only");
  EXPECT_EQ(warnings[1],
            "model.modes = 4 does not change a static analysis: modal reduction applies to "
            "transient analyses only (analysis.integrator = \"modal\")");
  EXPECT_EQ(warnings[2],
            "loads.time_function = \"ramp\" does not change a static analysis: it sets how the "
            "loads vary in transient analyses only");

  args.insert(args.end(), {"--set", "analysis.type=modal"});
  const nlohmann::json modal = RunJson(args);
  ASSERT_EQ(modal.at("warnings").size(), 3u);
  EXPECT_EQ(modal["warnings"][0],
            "effects.damping does not change a modal analysis: its frequencies and modes are "
            "those of the undamped beam");
  // A damping table switched off asks for nothing.
  const nlohmann::json off =
      RunJson({"cantilever", "--set", "effects.damping={ enabled = false }"});
  EXPECT_EQ(off.at("warnings"), nlohmann::json::array());

  const CliOutcome summary = Cli({"run", "cantilever", "--set", "model.modes=4"});
  EXPECT_EQ(summary.code, 0);
  ExpectContains(summary.out, "warning: model.modes = 4 does not change a static analysis");
}

TEST(TransientCliTest, TransientErrorsAreOneLineWithExitTwo) {
  EXPECT_EQ(InvalidInput({"run", "cantilever-release", "--set", "analysis.alpha=0.1"}),
            "cosmems: --set: analysis.alpha = 0.1: only the \"hht\" integrator takes it\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever-release", "--set", "analysis.integrator=newmark"}),
            "cosmems: cantilever-release: model.modes = 4: modal reduction needs "
            "analysis.integrator = \"modal\" (0: the full model)\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever-release", "--set", "analysis.time_step=2e-3"}),
            "cosmems: --set: analysis.time_step = 0.002: must not exceed analysis.duration = "
            "0.001\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever-release", "--set", "analysis.initial=rest", "--set",
                          "loads.time_function=sine"}),
            "cosmems: --set: loads.time_function = \"sine\": needs loads.frequency (Hz, > 0)\n");
  EXPECT_EQ(InvalidInput({"run", "cantilever-release", "--set", "loads.time_function=ramp", "--set",
                          "loads.ramp_time=1e-5"}),
            "cosmems: --set: loads.time_function = \"ramp\": analysis.initial = \"static\" "
            "removes the loads at t = 0, so only \"step\" goes with it\n");
}

}  // namespace
}  // namespace cosmems
