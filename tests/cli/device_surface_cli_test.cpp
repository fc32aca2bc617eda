// Surface forces under a device from the CLI: the Casimir pressure joins the electrodes' pull
// and lowers the serpentine plate's pull-in voltage, holds the plate or, at a smaller gap, pulls
// it in on its own; the gas film damps the swing a voltage step gives the plate; the contact
// stops the plate a step past its pull-in voltage snaps onto the substrate; and what a device
// cannot take with them is refused naming the key.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace cosmems {
namespace {

using testing::ExpectContains;
using testing::InvalidInput;
using testing::RunJson;

// At a 0.2 um gap the Casimir pressure, pi^2 hbar c / 240 g^4 = 0.8 Pa, is 2 % of the electrode's
// on the plate at the fold (k g / 3 A = 43 Pa); it also pulls the springs, which the electrode
// does not reach, and grows as 1/g^4 toward the fold: the voltage falls by ~5 % (5.1 % measured),
// between 1 % and 10 % asserted. SolveFramePullIn's fold with Casimir is checked against the
// plate's closed balance in frame_surface_test.cpp.
TEST(DeviceSurfaceCliTest, CasimirLowersTheSerpentinePlatesPullInVoltage) {
  const nlohmann::json without = RunJson({"serpentine-pullin", "--set", "structure.gap=0.2e-6"});
  const nlohmann::json with = RunJson({"serpentine-pullin", "--set", "structure.gap=0.2e-6",
                                       "--set", "effects.casimir.enabled=true"});
  ASSERT_EQ(with["status"], "ok");
  const double ratio =
      with["pullin_voltage_v"].get<double>() / without["pullin_voltage_v"].get<double>();
  EXPECT_LT(ratio, 0.99);
  EXPECT_GT(ratio, 0.9);
}

// A 10 V step swings the free plate past its rest by more than half of it; on the air under it
// (the plate's Reynolds film and the springs' strips, zeta ~ 2 for the plate alone) it creeps
// toward its rest without passing it, within 5 % of it after the run's 100 us.
TEST(DeviceSurfaceCliTest, TheGasFilmDampsThePlatesSwing) {
  const nlohmann::json statics =
      RunJson({"serpentine-pullin", "--set", "analysis.type=\"static\""});
  const double rest = -statics["bodies"]["plate"]["displacement"][1].get<double>();
  const std::vector<std::string> transient = {
      "serpentine-pullin",      "--set", "analysis.type=\"transient\"", "--set",
      "analysis.duration=1e-4", "--set", "analysis.time_step=2e-7"};
  const nlohmann::json free = RunJson(transient);
  std::vector<std::string> damped = transient;
  damped.insert(damped.end(), {"--set", "effects.squeeze_film.viscosity=1.81e-5"});
  const nlohmann::json film = RunJson(damped);
  ASSERT_EQ(film["status"], "ok");
  EXPECT_GT(free["displacement_max"].get<double>(), 1.5 * rest);
  EXPECT_LT(film["displacement_max"].get<double>(), rest);
  EXPECT_GT(film["displacement_max"].get<double>(), 0.95 * rest);
}

// Casimir alone in a static analysis: at 0.2 um the springs hold the plate a little way down
// (Casimir's fold lies at a fifth of the gap, k g / 5 A = 13 Pa against 0.8 Pa), with no warning;
// at 50 nm (200 Pa) no equilibrium exists: not converged, exit 3, and a warning that says why.
TEST(DeviceSurfaceCliTest, CasimirHoldsOrPullsInTheSerpentinePlate) {
  const std::vector<std::string> casimir = {"serpentine-pullin",
                                            "--set",
                                            "analysis.type=\"static\"",
                                            "--set",
                                            "effects.electrostatic.enabled=false",
                                            "--set",
                                            "effects.casimir.enabled=true"};
  std::vector<std::string> held = casimir;
  held.insert(held.end(), {"--set", "structure.gap=0.2e-6"});
  const nlohmann::json rest = RunJson(held);
  ASSERT_EQ(rest["status"], "ok");
  const double x = -rest["bodies"]["plate"]["displacement"][1].get<double>();
  EXPECT_GT(x, 0.0);
  EXPECT_LT(x, 0.2e-6 / 5.0);
  EXPECT_TRUE(rest.at("warnings").empty()) << rest.at("warnings");
  std::vector<std::string> closed = casimir;
  closed.insert(closed.end(), {"--set", "structure.gap=0.05e-6"});
  const nlohmann::json collapsed = RunJson(closed, 3);
  EXPECT_EQ(collapsed["status"], "not converged");
  ExpectContains(collapsed["warnings"].dump(), "the surface forces pull the structure onto");
  // With the contact 20 nm above the substrate the collapsed plate lies on the contact plane, 30
  // nm down, within the tolerance (1e-4 of the gap); the pressure is held at the plane's gap.
  closed.insert(closed.end(), {"--set", "effects.contact.separation=2e-8"});
  const nlohmann::json lying = RunJson(closed);
  ASSERT_EQ(lying["status"], "ok");
  EXPECT_TRUE(lying["collapsed"].get<bool>());
  EXPECT_EQ(lying["contact"]["state"], "contact");
  EXPECT_NEAR(lying["bodies"]["plate"]["displacement"][1].get<double>(), -3e-8, 1e-4 * 0.05e-6);
}

// Statics at 20 V, past the plate's pull-in voltage (13.1 V): with no floor there is no
// equilibrium (exit 3); with the contact the collapsed plate lies on the contact plane, the
// separation (0.2 um) above the substrate, within the tolerance (1e-4 of the gap), touching but
// not stuck, its springs clear of the substrate.
TEST(DeviceSurfaceCliTest, TheContactHoldsThePlatePulledInAtRest) {
  std::vector<std::string> pulled = {"serpentine-pullin", "--set", "analysis.type=\"static\"",
                                     "--set", "effects.electrostatic.voltage=20.0"};
  EXPECT_EQ(RunJson(pulled, 3)["status"], "not converged");
  pulled.insert(pulled.end(), {"--set", "effects.contact.separation=0.2e-6"});
  const nlohmann::json lying = RunJson(pulled);
  ASSERT_EQ(lying["status"], "ok");
  EXPECT_TRUE(lying["collapsed"].get<bool>());
  EXPECT_EQ(lying["contact"]["state"], "contact");
  EXPECT_NEAR(lying["bodies"]["plate"]["displacement"][1].get<double>(), -1.8e-6, 1e-4 * 2e-6);
  EXPECT_FALSE(lying["bodies"]["plate"]["stuck"].get<bool>());
  for (const nlohmann::json& member : lying["members"]) {
    EXPECT_EQ(member["contact_length_m"].get<double>(), 0.0) << member;
  }
}

// Under the hand at 20 V, past the plate's pull-in voltage (13.1 V), with the default separation
// (a hundredth of the gap, where the electrode's pull is steepest): the plate snaps onto the
// contact plane and lies there while the script presses it, and every tick of the second
// converges. A tick that failed would leave the structure where it was and the force to the
// safety layer's ramp.
TEST(DeviceSurfaceCliTest, ThePlatePulledInUnderTheHandLandsInEveryTick) {
  const nlohmann::json haptic = RunJson(
      {"serpentine-pullin", "--set", "analysis.type=\"haptic\"", "--set", "analysis.duration=1.0",
       "--set", "effects.electrostatic.voltage=20.0", "--set", "effects.contact.enabled=true"});
  ASSERT_EQ(haptic["status"], "ok");
  EXPECT_EQ(haptic["ticks"].get<int>(), 1001);
  EXPECT_EQ(haptic["physics"]["failed_ticks"].get<int>(), 0);
  EXPECT_GE(haptic["contact_events"]["contacts"].get<int>(), 1);
  EXPECT_EQ(haptic["contact"]["state"], "contact");
}

// A 20 V step, past the plate's pull-in voltage (13.1 V), snaps it down: with no floor the step
// that would cross the gap fails (exit 3, its matrix indefinite); with the contact the
// plate lands on the contact plane, the separation (0.2 um) above the substrate, and lies there
// to the contact's tolerance (1e-4 of the gap) for the rest of the run, touched once. The
// generalised-alpha integrator with rho_inf = 0.5 adds no energy at the impact (Newmark's
// average acceleration, which does, is warned against).
TEST(DeviceSurfaceCliTest, TheContactCatchesThePlatePulledIn) {
  std::vector<std::string> step = {"serpentine-pullin",
                                   "--set",
                                   "analysis.type=\"transient\"",
                                   "--set",
                                   "analysis.duration=1e-4",
                                   "--set",
                                   "analysis.time_step=2e-7",
                                   "--set",
                                   "analysis.integrator=\"generalized-alpha\"",
                                   "--set",
                                   "analysis.rho_inf=0.5",
                                   "--set",
                                   "effects.electrostatic.voltage=20.0"};
  EXPECT_NE(RunJson(step, 3)["status"], "ok");
  step.insert(step.end(), {"--set", "effects.contact.separation=0.2e-6"});
  const nlohmann::json caught = RunJson(step);
  ASSERT_EQ(caught["status"], "ok");
  const double landed = 2e-6 - 0.2e-6;
  EXPECT_NEAR(caught["displacement_max"].get<double>(), landed, 1e-4 * 2e-6);
  EXPECT_EQ(caught["contact"]["state"], "contact");
  EXPECT_TRUE(caught["contact"]["contact_length_m"].is_null());
  EXPECT_EQ(caught["contact_events"]["contacts"], 1);
}

// The embedded cantilever (200 x 20 x 2 um, silicon, 2 um over the substrate) as the one member
// of a frame, in `elements` elements: the device the beam's surface analyses are checked against.
std::string CantileverMember(int elements) {
  return R"([structure]
kind = "frame"
thickness = 2e-6
gap = 2e-6
[[structure.nodes]]
name = "clamp"
position = [0.0, 0.0, 0.0]
support = "clamped"
[[structure.nodes]]
name = "tip"
position = [200e-6, 0.0, 0.0]
[[structure.beams]]
nodes = ["clamp", "tip"]
width = 20e-6
[material]
young_modulus = 169e9
density = 2330.0
[model]
dimension = 3
elements = )" +
         std::to_string(elements) + "\n";
}

// cantilever-stiction's beam as a member of a frame, released from the substrate: stuck in the S
// shape with the beam's free span and length on the substrate (the same elements and crack front:
// equal to round-off), reported for the structure as for its one member, and nodes.csv holds the
// tip lying down.
TEST(DeviceSurfaceCliTest, ACantileverMemberReleasesAsTheCantilever) {
  const testing::TempDirectory dir("frame_release");
  testing::WriteFile(dir.path() / "member.toml", CantileverMember(100) + R"(
[effects]
stiction = { adhesion_energy = 0.02 }
[analysis]
type = "release"
)");
  const nlohmann::json beam = RunJson({"cantilever-stiction"});
  const nlohmann::json device =
      RunJson({(dir.path() / "member.toml").string(), "--out", (dir.path() / "out").string()});
  ASSERT_EQ(device["status"], "ok");
  EXPECT_TRUE(device["stuck"].get<bool>());
  EXPECT_EQ(device["shape"], "s");
  const nlohmann::json& member = device["members"][0];
  // One member: the structure's lengths, at the top and in `contact`, are its member's.
  for (const char* key : {"detached_length_m", "contact_length_m"}) {
    EXPECT_EQ(device[key], member[key]) << key;
    EXPECT_EQ(device["contact"][key], member[key]) << key;
  }
  EXPECT_EQ(member["nodes"], nlohmann::json({"clamp", "tip"}));
  EXPECT_EQ(member["shape"], beam["shape"]);
  const double span = beam["detached_length_m"].get<double>();
  EXPECT_NEAR(member["detached_length_m"].get<double>(), span, 1e-12 * span);
  EXPECT_NEAR(member["contact_length_m"].get<double>(), beam["contact_length_m"].get<double>(),
              1e-12 * span);
  EXPECT_NEAR(device["nodes"]["tip"]["displacement"][1].get<double>(), -2e-6, 1e-4 * 2e-6);
  const std::vector<std::string> rows = testing::ReadLines(dir.path() / "out" / "nodes.csv");
  ASSERT_EQ(rows.size(), 3U);
  ExpectContains(rows[2], "tip,");
}

// A one-member netlist's transient with contact reports its lengths as its release and the
// cantilever do (one rule, HasContactLengths): driven onto the substrate by a tip force, it ends
// with a free span and a length on the substrate that are numbers, not null, and within the
// member's length.
TEST(DeviceSurfaceCliTest, ACantileverMembersTransientReportsItsContactLengths) {
  const testing::TempDirectory dir("frame_transient_contact");
  testing::WriteFile(dir.path() / "member.toml", CantileverMember(20) + R"(
[[loads.points]]
node = "tip"
force = [0.0, -3e-6, 0.0]
[effects]
contact = { enabled = true }
[analysis]
type = "transient"
duration = 1e-4
time_step = 1e-7
record = ["tip"]
)");
  const nlohmann::json device = RunJson({(dir.path() / "member.toml").string()});
  ASSERT_EQ(device["status"], "ok");
  const nlohmann::json& contact = device["contact"];
  EXPECT_GE(device["contact_events"]["contacts"].get<int>(), 1);
  ASSERT_TRUE(contact["detached_length_m"].is_number());
  ASSERT_TRUE(contact["contact_length_m"].is_number());
  EXPECT_GT(contact["detached_length_m"].get<double>(), 0.0);
  EXPECT_LE(contact["detached_length_m"].get<double>() + contact["contact_length_m"].get<double>(),
            200e-6 * (1.0 + 1e-12));
}

// The cantilever's static pressed onto the substrate by a tip force 3.5 times what closes the gap,
// with stiction, as a frame member and as the beam (the same 20 Hermite elements): both tips lie
// on the contact plane within its tolerance (1e-4 of the gap), stuck, and the clamp's stress,
// (F - R) L c / I with R the substrate's push, is the same to 1e-6 (the tips' places differ
// within the tolerance, and with them R).
TEST(DeviceSurfaceCliTest, ACantileverMemberPressedOntoTheSubstrateIsTheCantilever) {
  const testing::TempDirectory dir("frame_static_contact");
  testing::WriteFile(dir.path() / "member.toml", CantileverMember(20) + R"(
[[loads.points]]
node = "tip"
force = [0.0, -6e-6, 0.0]
[effects]
stiction = { adhesion_energy = 0.02 }
[analysis]
type = "static"
)");
  const nlohmann::json beam = RunJson({"cantilever", "--set", "loads.tip_force=[0.0, -6e-6, 0.0]",
                                       "--set", "effects.stiction.adhesion_energy=0.02"});
  const nlohmann::json device = RunJson({(dir.path() / "member.toml").string()});
  ASSERT_EQ(beam["status"], "ok");
  ASSERT_EQ(device["status"], "ok");
  EXPECT_FALSE(device["collapsed"].get<bool>());
  EXPECT_EQ(device["contact"]["state"], beam["contact"]["state"]);
  EXPECT_EQ(device["members"][0]["stuck"], true);
  const double tolerance = 1e-4 * 2e-6;
  EXPECT_NEAR(device["nodes"]["tip"]["displacement"][1].get<double>(), -2e-6, tolerance);
  EXPECT_NEAR(beam["tip_displacement"][1].get<double>(), -2e-6, tolerance);
  const double stress = beam["max_stress_pa"].get<double>();
  EXPECT_NEAR(device["max_stress_pa"].get<double>(), stress, 1e-6 * stress);
}

TEST(DeviceSurfaceCliTest, SurfaceForcesWhereTheyCannotActAreRefused) {
  ExpectContains(
      InvalidInput({"run", "serpentine-pullin", "--set", "effects.contact.enabled=true"}),
      "effects.contact");
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set", "analysis.type=\"modal\"",
                               "--set", "effects.electrostatic.enabled=false", "--set",
                               "effects.stiction.adhesion_energy=0.02"}),
                 "effects.stiction = { adhesion_energy = 0.02 }: not available for "
                 "analysis.type = \"modal\"");
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set", "analysis.type=\"haptic\"",
                               "--set", "analysis.integrator=\"modal\"", "--set", "model.modes=4",
                               "--set", "effects.damping.quality_factor=100.0", "--set",
                               "effects.stiction.adhesion_energy=0.02"}),
                 "analysis.integrator = \"modal\" takes no adhesion on a device");
  ExpectContains(
      InvalidInput({"run", "serpentine-pullin", "--set", "analysis.type=\"transient\"", "--set",
                    "analysis.duration=1e-5", "--set", "analysis.time_step=1e-7", "--set",
                    "analysis.integrator=\"modal\"", "--set", "model.modes=4", "--set",
                    "effects.squeeze_film.viscosity=1.81e-5"}),
      "effects.squeeze_film");
  ExpectContains(
      InvalidInput({"run", "serpentine-pullin", "--set", "effects.van_der_waals.enabled=true"}),
      "effects.van_der_waals");
  ExpectContains(InvalidInput({"run", "serpentine-pullin", "--set", "analysis.type=\"modal\"",
                               "--set", "effects.electrostatic.enabled=false", "--set",
                               "effects.casimir.enabled=true"}),
                 "effects.casimir");
}

}  // namespace
}  // namespace cosmems
