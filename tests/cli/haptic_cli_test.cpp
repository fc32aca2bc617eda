// The haptic analysis through the command line: the default scene's scripted stylus presses the
// tip onto the substrate; as fast as possible (realtime = false) the run is deterministic.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace cosmems {
namespace {

using testing::Cli;
using testing::CliOutcome;
using testing::ExpectContains;
using testing::InvalidInput;
using testing::ReadLines;
using testing::RunJson;
using testing::TempDirectory;
using testing::WriteFile;

const std::vector<std::string> kFast = {"--set", "device.realtime=false", "--set",
                                        "analysis.duration=2.0"};

std::vector<std::string> Args(std::vector<std::string> args) {
  args.insert(args.end(), kFast.begin(), kFast.end());
  return args;
}

TEST(HapticCliTest, TheScriptedPressTouchesTheSubstrateWithinTheDeviceLimits) {
  const TempDirectory dir;
  const nlohmann::json json = RunJson(Args({"cantilever-haptic", "--out", dir.path().string()}));
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("ticks").get<long>(), 2001);  // at 0, 1 ms, ..., 2 s
  EXPECT_FALSE(json.at("paced").get<bool>());
  EXPECT_EQ(json.at("deadline_misses").get<long>(), 0);
  const double limit = json.at("force_limit_n").get<double>();
  EXPECT_DOUBLE_EQ(limit, 0.88);  // the Omni's continuous force
  EXPECT_LE(json.at("max_device_force_n").get<double>(), limit * (1 + 1e-12));
  EXPECT_GT(json.at("max_device_force_n").get<double>(), 0.1 * limit);  // it was felt
  EXPECT_GE(json.at("proximity_warnings").get<long>(), 1);
  EXPECT_GE(json.at("contact_events").at("contacts").get<long>(), 1);
  EXPECT_EQ(json.at("physics").at("failed_ticks").get<long>(), 0);
  const std::vector<std::string> lines = ReadLines(dir.path() / "device_forces.csv");
  ASSERT_EQ(lines.size(), 2002u);  // the header and a row a tick
  EXPECT_EQ(lines[0], "time_s,x_m,y_m,z_m,fx_n,fy_n,fz_n");
  // The same run again gives the same forces, tick for tick.
  const TempDirectory again("_again");
  RunJson(Args({"cantilever-haptic", "--out", again.path().string()}));
  EXPECT_EQ(ReadLines(again.path() / "device_forces.csv"), lines);
}

// In 3-D (numbered node by node, so that the probe may twist the beam) the press runs the same.
TEST(HapticCliTest, TheSpatialBeamIsPressedOntoTheSubstrateToo) {
  const nlohmann::json json = RunJson(Args({"cantilever-haptic", "--set", "model.dimension=3"}));
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("physics").at("failed_ticks").get<long>(), 0);
  EXPECT_GE(json.at("contact_events").at("stuck_events").get<long>(), 1);
  EXPECT_LE(json.at("max_device_force_n").get<double>(),
            json.at("force_limit_n").get<double>() * (1 + 1e-12));
}

// The modal path: eight damped modes instead of the full model, the same press, the same bounds.
TEST(HapticCliTest, TheModalPathRunsThePressWithinTheDeviceLimits) {
  const nlohmann::json json =
      RunJson(Args({"cantilever-haptic", "--set", "analysis.integrator=\"modal\"", "--set",
                    "model.modes=8", "--set", "effects.damping.quality_factor=100.0"}));
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("physics").at("failed_ticks").get<long>(), 0);
  EXPECT_GE(json.at("contact_events").at("contacts").get<long>(), 1);
  EXPECT_GT(json.at("max_device_force_n").get<double>(),
            0.1 * json.at("force_limit_n").get<double>());
  EXPECT_LE(json.at("max_device_force_n").get<double>(),
            json.at("force_limit_n").get<double>() * (1 + 1e-12));
  EXPECT_TRUE(json.at("warnings").empty()) << json.at("warnings");
}

// The press sticks the tip; when the stylus lifts, a cantilever longer than the arc-shaped
// detachment length (100 um here, with the scene's 20 nm asperities) stays held by its tip,
// arc-shaped, and a shorter one springs free.
TEST(HapticCliTest, AfterThePressTheTipStaysStuckArcShapedOrSpringsFree) {
  const nlohmann::json arc =
      RunJson(Args({"cantilever-haptic", "--set", "structure.length=120e-6"}));
  EXPECT_EQ(arc.at("status"), "ok");
  EXPECT_EQ(arc.at("contact").at("state"), "stuck");
  EXPECT_EQ(arc.at("contact").at("shape"), "arc");
  EXPECT_EQ(arc.at("contact_events").at("releases").get<long>(), 0);
  const nlohmann::json free =
      RunJson(Args({"cantilever-haptic", "--set", "structure.length=90e-6"}));
  EXPECT_EQ(free.at("contact").at("shape"), "free");
  EXPECT_GE(free.at("contact_events").at("stuck_events").get<long>(), 1);
  EXPECT_EQ(free.at("contact_events").at("releases").get<long>(), 1);
}

// The OpenHaptics backend from the command line: without the SDK, the project's fake Omni, whose
// stylus rests at the workspace's centre, a tenth of the clearance into the beam's upper face.
TEST(HapticCliTest, TheOpenHapticsBackendRunsTheSceneForItsDuration) {
  const nlohmann::json json =
      RunJson({"cantilever-haptic", "--set", "device.backend=\"openhaptics\"", "--set",
               "analysis.duration=0.5"});
  EXPECT_EQ(json.at("status"), "ok");
  const nlohmann::json& device = json.at("device");
  EXPECT_EQ(device.at("backend"), "openhaptics");
  EXPECT_EQ(device.at("model"), "PHANTOM Omni");
  EXPECT_EQ(device.at("calibration"), "calibrated");
  EXPECT_EQ(json.at("safety").at("uncalibrated_ticks"), 0);
  EXPECT_TRUE(json.at("paced").get<bool>());
  // It ran for the scene's 0.5 s. How many ticks the device scheduler ran in that time is the
  // machine's business (bench/haptic_run_bench measures the rate): here only that it ticked.
  EXPECT_GE(json.at("wall_time_s").get<double>(), 0.5);
  EXPECT_GT(json.at("ticks").get<double>(), 0.0);
  EXPECT_LE(json.at("max_device_force_n").get<double>(),
            json.at("force_limit_n").get<double>() * (1 + 1e-12));
  if (device.at("hd_library") == "fake") {
    EXPECT_GT(json.at("max_device_force_n").get<double>(), 0.0);  // it rests in the beam
    ExpectContains(json.at("warnings").dump(), "fake of the HD API");
  }
}

// The recorded forces of --out appear whole or not at all, and a symbolic link in their place is
// replaced, never written through.
TEST(HapticCliTest, TheRecordedForcesNeverWriteThroughASymbolicLink) {
  const TempDirectory dir;
  const std::filesystem::path precious = dir.path() / "precious.txt", out = dir.path() / "out";
  WriteFile(precious, "precious\n");
  std::filesystem::create_directories(out);
  std::filesystem::create_symlink(precious, out / "device_forces.csv");
  const CliOutcome run =
      Cli({"run", "cantilever-haptic", "--set", "device.realtime=false", "--out", out.string()});
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(ReadLines(precious), std::vector<std::string>{"precious"});
  EXPECT_FALSE(std::filesystem::is_symlink(out / "device_forces.csv"));
  const std::vector<std::string> lines = ReadLines(out / "device_forces.csv");
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.front(), "time_s,x_m,y_m,z_m,fx_n,fy_n,fz_n");
  EXPECT_GT(lines.size(), 6000u);  // 6 s of ticks at 1 kHz, and the header
}

// A device is touched as a beam is: the scripted stylus presses the folded flexure's first body
// (the truss "truss_low") from above, or a node or body named by device.target.
TEST(HapticCliTest, TheStylusPressesADevicesBodyOrNode) {
  const std::vector<std::string> haptic = {"--set", "analysis.type=\"haptic\""};
  std::vector<std::string> device = Args({"folded-flexure"});
  device.insert(device.end(), haptic.begin(), haptic.end());
  const nlohmann::json json = RunJson(device);
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("ticks").get<long>(), 2001);
  EXPECT_EQ(json.at("physics").at("failed_ticks").get<long>(), 0);
  const double limit = json.at("force_limit_n").get<double>();
  EXPECT_LE(json.at("max_device_force_n").get<double>(), limit * (1 + 1e-12));
  EXPECT_GT(json.at("max_device_force_n").get<double>(), 0.05 * limit);  // it was felt
  // The coupling is 25 times the structure under the stylus: the stiffness toward the substrate
  // of the first body, a truss.
  const double truss_coupling = json.at("scaling").at("coupling_stiffness_n_per_m").get<double>();
  ExpectContains(json.at("warnings").dump(), "loads does not change a haptic analysis");
  // The summary leaves out the substrate contact, which does not act on a device; a beam with
  // contact shows its state.
  std::vector<std::string> text = {"run"};
  text.insert(text.end(), device.begin(), device.end());
  const testing::CliOutcome device_summary = testing::Cli(text);
  EXPECT_EQ(device_summary.code, 0);
  EXPECT_EQ(device_summary.out.find("substrate"), std::string::npos) << device_summary.out;
  ExpectContains(testing::Cli(Args({"run", "cantilever-haptic"})).out, "substrate             ");
  // The other truss, its mirror image, is as stiff to round-off; the shuttle, which the trusses
  // hold level from both sides, is stiffer (measured 128.0 N/m against 42.36 N/m: the coupling
  // follows the target).
  const auto coupling_at = [&](const std::string& target) {
    std::vector<std::string> args = device;
    args.insert(args.end(), {"--set", "device.target=\"" + target + "\""});
    const nlohmann::json pressed = RunJson(args);
    EXPECT_EQ(pressed.at("physics").at("failed_ticks").get<long>(), 0) << target;
    return pressed.at("scaling").at("coupling_stiffness_n_per_m").get<double>();
  };
  EXPECT_NEAR(coupling_at("truss_high"), truss_coupling, 1e-9 * truss_coupling);
  EXPECT_GT(coupling_at("shuttle"), 2.0 * truss_coupling);
  ExpectContains(InvalidInput({"run", "folded-flexure", "--set", "analysis.type=\"haptic\"",
                               "--set", "device.target=\"anchor\""}),
                 "device.target = \"anchor\": no node or body \"anchor\"");
  ExpectContains(InvalidInput({"run", "folded-flexure", "--set", "analysis.type=\"haptic\"",
                               "--set", "device.target=\"anchor_left_low\""}),
                 "device.target = \"anchor_left_low\": a press there moves nothing");
  ExpectContains(InvalidInput({"run", "cantilever-haptic", "--set", "device.target=\"tip\""}),
                 "device.target = \"tip\": names a device's node or body");
}

TEST(HapticCliTest, RefusesWhatItCannotDriveByName) {
  ExpectContains(
      InvalidInput(Args({"run", "cantilever-haptic", "--set", "device.force_scale=1e9"})),
      "device.force_scale = 1");
  ExpectContains(
      InvalidInput(Args({"run", "cantilever-haptic", "--set", "device.trajectory=\"spiral\""})),
      "device.trajectory");
}

}  // namespace
}  // namespace cosmems
