// Frames through the CLI: the JSON of a device's static and modal analyses against closed
// forms, and the errors that name a netlist's entry and key.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cli_test_support.hpp"
#include "cosmems/core/constants.hpp"

namespace cosmems {
namespace {

using testing::ExpectContains;
using testing::InvalidInput;
using testing::RunJson;
using testing::TempDirectory;
using testing::WriteFile;

// A 60 x 40 um plate held at its corners by four 100 um beams along x from their anchors,
// pressed at its centre: out of plane each beam is clamped-guided, k = 4 x 12 E I / L^3.
std::string Plate(const std::string& extra = "") {
  std::string text = R"(
[structure]
kind = "frame"
thickness = 2e-6

[materials.poly]
young_modulus = 160e9
density = 2330.0

[model]
elements = 4

[analysis]
type = "static"

[[loads.points]]
body = "plate"
force = [0.0, -1e-6, 0.0]

[[structure.bodies]]
name = "plate"
center = [0.0, 0.0, 0.0]
size = [60e-6, 2e-6, 40e-6]
nodes = ["c0", "c1", "c2", "c3"]
material = "poly"
)";
  const char* sign[4][2] = {{"-", "-"}, {"-", ""}, {"", "-"}, {"", ""}};
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i);
    text += "\n[[structure.nodes]]\nname = \"a" + n + "\"\nposition = [" + sign[i][0] +
            "130e-6, 0.0, " + sign[i][1] + "20e-6]\nsupport = \"clamped\"\n";
    text += "\n[[structure.nodes]]\nname = \"c" + n + "\"\nposition = [" + sign[i][0] +
            "30e-6, 0.0, " + sign[i][1] + "20e-6]\n";
    text += "\n[[structure.beams]]\nnodes = [\"a" + n + "\", \"c" + n +
            "\"]\nwidth = 2e-6\nmaterial = \"poly\"\n";
  }
  return text + extra;
}

TEST(FrameCliTest, APlateOnFourBeamsSinksByTheirStiffnessAndTheAnchorsHoldTheLoad) {
  const TempDirectory dir;
  WriteFile(dir.path() / "plate.toml", Plate());
  const nlohmann::json json = RunJson({(dir.path() / "plate.toml").string()});
  const double ei = 160e9 * 2e-6 * 8e-18 / 12;
  const double k = 4 * 12 * ei / 1e-12;
  const double sink = json["bodies"]["plate"]["displacement"][1];
  EXPECT_NEAR(sink, -1e-6 / k, 1e-10 / k);  // nodally exact: round-off
  EXPECT_NEAR(json["max_deflection"].get<double>(), 1e-6 / k, 1e-10 / k);
  double held = 0.0;
  for (const auto& [name, reaction] : json["reactions"].items()) {
    held += reaction["force"][1].get<double>();
  }
  EXPECT_NEAR(held, 1e-6, 1e-15);
  EXPECT_EQ(json["reactions"].size(), 4u);
  EXPECT_EQ(json["nodes"].size(), 8u);
  EXPECT_EQ(json["model"]["elements"], 16);
  EXPECT_EQ(json["status"], "ok");
}

TEST(FrameCliTest, TheMicromirrorTwistsAtGJOverLAndItsPlatesInertia) {
  const nlohmann::json json = RunJson({"micromirror"});
  // Two 100 um torsion beams, 3 x 2 um, on a 100 x 100 x 2 um plate; the beams' own inertia
  // (a third of rho I_p L each) moves the frequency by 1e-5, so it is taken in.
  const double w = 3e-6, t = 2e-6, l = 100e-6;
  const double a = std::max(w, t), c = std::min(w, t), r = c / a;
  const double j = a * c * c * c * (1.0 / 3.0 - 0.21 * r * (1.0 - r * r * r * r / 12.0));
  const double g = 160e9 / (2 * 1.22);
  const double plate = 2330.0 * 100e-6 * 2e-6 * 100e-6 * (1e-8 + 4e-12) / 12;
  const double beams = 2 * 2330.0 * (w * t * (w * w + t * t) / 12) * l / 3;
  const double expected = std::sqrt(2 * g * j / l / (plate + beams)) / (2 * kPi);
  const nlohmann::json& first = json["modes"][0];
  EXPECT_EQ(first["kind"], "torsion");
  EXPECT_NEAR(first["frequency_hz"].get<double>(), expected, 1e-6 * expected);
  EXPECT_GT(first["participation"]["rx"].get<double>(), 0.999);
  EXPECT_LT(first["participation"]["uy"].get<double>(), 1e-12);
  EXPECT_EQ(json["frequencies_hz"].size(), 4u);
}

TEST(FrameCliTest, StaticAndModalFilesListEveryNodeAndBody) {
  const TempDirectory dir;
  WriteFile(dir.path() / "plate.toml", Plate());
  const std::string scene = (dir.path() / "plate.toml").string();
  ASSERT_EQ(testing::Cli({"run", scene, "--out", (dir.path() / "s").string()}).code, 0);
  EXPECT_EQ(testing::ReadLines(dir.path() / "s" / "nodes.csv").size(), 1u + 8u + 1u);
  EXPECT_EQ(testing::ReadLines(dir.path() / "s" / "reactions.csv").size(), 1u + 4u);
  ASSERT_EQ(testing::Cli({"run", scene, "--set", "analysis.type=\"modal\"", "--out",
                          (dir.path() / "m").string()})
                .code,
            0);
  EXPECT_EQ(testing::ReadLines(dir.path() / "m" / "modes.csv").size(), 1u + 4u);
  EXPECT_EQ(testing::ReadLines(dir.path() / "m" / "mode_shapes.csv").size(), 1u + 4u * 9u);
}

TEST(FrameCliTest, NetlistErrorsNameTheEntryAndTheKey) {
  const TempDirectory dir;
  auto error = [&](const std::string& text, const std::vector<std::string>& extra = {}) {
    WriteFile(dir.path() / "bad.toml", text);
    std::vector<std::string> args = {"run", (dir.path() / "bad.toml").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return InvalidInput(args);
  };
  std::string text = Plate();
  text.replace(text.find("nodes = [\"a2\", \"c2\"]"), 20, "nodes = [\"a2\", \"x2\"]");
  ExpectContains(error(text), "structure.beams[2].nodes = [\"a2\", \"x2\"]: no node \"x2\"");
  // A name with a control character, quoted in the value as TOML writes it and in the reason
  // escaped, never as the raw byte.
  text = Plate();
  text.replace(text.find("nodes = [\"a2\", \"c2\"]"), 20, "nodes = [\"a2\", \"\\u001b[2J\"]");
  ExpectContains(error(text),
                 "structure.beams[2].nodes = [\"a2\", \"\\u001B[2J\"]: no node \"\\x1B[2J\"");
  text = Plate();
  text.replace(text.find("body = \"plate\""), 14, "body = \"slab\"");
  ExpectContains(error(text), "loads.points[0].body = \"slab\": no body \"slab\"");
  ExpectContains(error(Plate("\n[[loads.points]]\nnode = \"c1\"\nbody = \"plate\"\n")),
                 "loads.points[1]");
  ExpectContains(error(Plate(), {"--set", "analysis.type=\"release\""}),
                 "effects.stiction: analysis.type = \"release\" lets the structure go from the "
                 "substrate");
  ExpectContains(error(Plate(), {"--set", "structure.length=1e-4"}),
                 "structure.length = 1e-04: only a cantilever or a bridge takes it");
  ExpectContains(error(Plate("\n[loads]\ntip_force = [0.0, 1e-6, 0.0]\n")), "loads.tip_force");
  text = Plate();
  text.replace(text.find("material = \"poly\""), 17, "material = \"oxide\"");
  ExpectContains(error(text), "no [materials.oxide] table");
  text = Plate();
  const std::string corners = "nodes = [\"c0\", \"c1\", \"c2\", \"c3\"]";
  text.replace(text.find(corners), corners.size(), "nodes = []");
  ExpectContains(error(text),
                 "structure.bodies[0].nodes = []: expected an array of one or more names");
  text = Plate();
  text.replace(text.find("position = [-30e-6"), 18, "position = [-130e-6");
  ExpectContains(error(text), "structure.beams[0].nodes = [\"a0\", \"c0\"]: zero length");
  ExpectContains(error(Plate("\n[[structure.nodes]]\nname = \"c1\"\nposition = [0.0, 0.0, 0.0]\n")),
                 "structure.nodes[8].name = \"c1\": already the name of structure.nodes[3]");
  text = Plate();
  text.replace(text.find("support = \"clamped\""), 19, "support = \"welded\"");
  ExpectContains(error(text), "structure.nodes[0].support = \"welded\": expected \"free\"");
}

// The folded-flexure resonator's generator from the CLI: the shuttle moves F / k along x with
// k = 24 E I / L^3, a design parameter changes by --set, and the netlist it prints runs to the
// same results.
TEST(FrameCliTest, TheFoldedFlexureMovesByItsDesignsStiffnessAndPrintsItsNetlist) {
  const double k = 2 * 160e9 * 2e-6 * 8e-18 / 1e-12;  // 2 E t w^3 / L^3
  const nlohmann::json json = RunJson({"folded-flexure"});
  const double moved = json["bodies"]["shuttle"]["displacement"][0];
  EXPECT_NEAR(moved, 1e-6 / k, 1e-10 / k);
  const nlohmann::json longer =
      RunJson({"folded-flexure", "--set", "structure.beam_length=150e-6"});
  EXPECT_NEAR(longer["bodies"]["shuttle"]["displacement"][0].get<double>(), moved * 1.5 * 1.5 * 1.5,
              1e-9 * moved);
  EXPECT_EQ(json["model"]["elements"], 80);

  const testing::CliOutcome netlist = testing::Cli({"netlist", "folded-flexure"});
  ASSERT_EQ(netlist.code, 0) << netlist.err;
  ExpectContains(netlist.out, "kind = \"frame\"");
  const TempDirectory dir;
  WriteFile(dir.path() / "netlist.toml", netlist.out);
  const nlohmann::json again = RunJson({(dir.path() / "netlist.toml").string()});
  for (const auto& [name, node] : json["nodes"].items()) {
    for (int k3 = 0; k3 < 3; ++k3) {
      EXPECT_NEAR(again["nodes"][name]["displacement"][k3].get<double>(),
                  node["displacement"][k3].get<double>(), 1e-12 * moved)
          << name;
    }
  }
  EXPECT_EQ(again["reactions"].size(), json["reactions"].size());

  ExpectContains(InvalidInput({"run", "folded-flexure", "--set", "structure.shuttle_width=10e-6"}),
                 "structure.shuttle_width = 1e-05: too narrow for the beams");
  ExpectContains(InvalidInput({"run", "folded-flexure", "--set", "structure.length=1e-4"}),
                 "only a cantilever or a bridge takes it");
  ExpectContains(InvalidInput({"netlist", "micromirror"}), "is a netlist already");
}

// The folded flexure's shuttle under a step force F rings about F / k, overshooting to 2 F / k,
// with every integrator: the full model's Newmark family and six modes propagated exactly
// (whose missing fast modes ring at a hundredth of the motion: tests/structure). history.csv
// holds the recorded points, then the other bodies.
TEST(FrameCliTest, TheFoldedFlexureRingsAboutItsStaticDeflectionInATransient) {
  const double k = 2 * 160e9 * 2e-6 * 8e-18 / 1e-12;  // 2 E t w^3 / L^3
  const std::vector<std::string> transient = {"folded-flexure",
                                              "--set",
                                              "analysis.type=\"transient\"",
                                              "--set",
                                              "analysis.duration=2e-5",
                                              "--set",
                                              "analysis.time_step=5e-8",
                                              "--set",
                                              "analysis.record=[\"shuttle\", \"joint_left_low\"]"};
  for (const char* integrator : {"newmark", "hht", "generalized-alpha", "modal"}) {
    std::vector<std::string> args = transient;
    args.insert(args.end(), {"--set", std::string("analysis.integrator=\"") + integrator + "\""});
    if (std::string(integrator) == "modal") args.insert(args.end(), {"--set", "model.modes=6"});
    const nlohmann::json json = RunJson(args);
    EXPECT_EQ(json["steps"], 400) << integrator;
    EXPECT_NEAR(json["displacement_max"].get<double>(), 2e-6 / k, 0.02 * 2e-6 / k) << integrator;
    EXPECT_EQ(json["watched"]["point"], "shuttle");
    EXPECT_EQ(json["watched"]["component"], "ux");
  }
  const TempDirectory dir;
  std::vector<std::string> args = transient;
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--out", dir.path().string()});
  ASSERT_EQ(testing::Cli(args).code, 0);
  const std::vector<std::string> history = testing::ReadLines(dir.path() / "history.csv");
  ASSERT_EQ(history.size(), 1u + 401u);
  ExpectContains(history[0],
                 "time_s,shuttle_ux_m,shuttle_uy_m,shuttle_uz_m,joint_left_low_ux_m,"
                 "joint_left_low_uy_m,joint_left_low_uz_m,truss_low_ux_m,");
  ExpectContains(history[0], "truss_high_uz_m");
  // The summary names the watched point, however long its name.
  args = transient;
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--set", "analysis.record=[\"joint_left_low\"]"});
  const testing::CliOutcome summary = testing::Cli(args);
  EXPECT_EQ(summary.code, 0);
  ExpectContains(summary.out, "| at joint_left_low ");

  args = transient;
  args.insert(args.begin(), "run");
  args.insert(args.end(), {"--set", "analysis.record=[\"nowhere\"]"});
  ExpectContains(InvalidInput(args),
                 "analysis.record = [\"nowhere\"]: no node or body \"nowhere\"");
  ExpectContains(InvalidInput({"run", "cantilever", "--set", "analysis.type=\"transient\"", "--set",
                               "analysis.duration=1e-5", "--set", "analysis.time_step=1e-7",
                               "--set", "analysis.record=[\"tip\"]"}),
                 "analysis.record = [\"tip\"]: only a device's transient takes it");
  WriteFile(dir.path() / "rod.toml", R"(
[structure]
kind = "frame"
thickness = 2e-6
[material]
young_modulus = 160e9
density = 2330.0
[[structure.nodes]]
name = "root"
position = [0.0, 0.0, 0.0]
support = "clamped"
[[structure.nodes]]
name = "tip"
position = [100e-6, 0.0, 0.0]
[[structure.beams]]
nodes = ["root", "tip"]
width = 2e-6
[analysis]
type = "transient"
duration = 1e-5
time_step = 1e-7
)");
  ExpectContains(InvalidInput({"run", (dir.path() / "rod.toml").string()}),
                 "analysis.record: structure.kind = \"frame\" has no body: name the nodes");
  const nlohmann::json tip =
      RunJson({(dir.path() / "rod.toml").string(), "--set", "analysis.record=[\"tip\"]"});
  EXPECT_EQ(tip["displacement_max"], 0.0);  // no load: at rest, and warned
  ExpectContains(tip["warnings"].dump(), "the device stays at rest");
}

// A column standing on the substrate, fixed at its foot and pressed at its top: the load factor
// that buckles it against Euler's pi^2 E I / (4 L^2) with the weaker bending (along x, the
// thickness direction it names); a device its loads do not compress does not buckle.
TEST(FrameCliTest, AColumnBucklesAtEulersLoadAndAPulledShuttleNever) {
  const TempDirectory dir;
  WriteFile(dir.path() / "column.toml", R"(
[structure]
kind = "frame"
thickness = 2e-6

[[structure.nodes]]
name = "foot"
position = [0.0, 0.0, 0.0]
support = "clamped"

[[structure.nodes]]
name = "top"
position = [0.0, 100e-6, 0.0]

[[structure.beams]]
nodes = ["foot", "top"]
width = 3e-6
thickness_direction = [1.0, 0.0, 0.0]

[material]
young_modulus = 160e9
density = 2330.0

[[loads.points]]
node = "top"
force = [0.0, -1e-6, 0.0]

[analysis]
type = "buckling"
)");
  const nlohmann::json json = RunJson({(dir.path() / "column.toml").string()});
  const double euler = kPi * kPi * 160e9 * (3e-6 * 8e-18 / 12) / (4 * 1e-8);
  // 20 Hermite elements with the consistent geometric stiffness: within 1e-7 of Euler's load.
  EXPECT_NEAR(json["critical_load_n"].get<double>(), euler, 1e-7 * euler);
  EXPECT_NEAR(json["load_factor"].get<double>(), euler / 1e-6, 1e-7 * euler / 1e-6);

  const nlohmann::json pulled =
      RunJson({"folded-flexure", "--set", "analysis.type=\"buckling\""}, 3);
  EXPECT_EQ(pulled["status"], "not converged");
  ExpectContains(pulled["warnings"].dump(), "the loads compress no member");
}

// A netlist that its supports do not hold is invalid input naming structure.nodes and the part
// that floats, found on the netlist before any model is built: a part with no support at all,
// and one whose supports leave it a rigid motion (anchors that fix only uy let the plate slide
// in its plane). The library's solvers still report such a model as not positive definite.
TEST(FrameCliTest, AnUnsupportedNetlistIsInvalidInputNamingThePartThatFloats) {
  const TempDirectory dir;
  auto error = [&](const std::string& text) {
    WriteFile(dir.path() / "loose.toml", text);
    return InvalidInput({"run", (dir.path() / "loose.toml").string()});
  };
  std::string text = Plate();
  for (std::size_t at; (at = text.find("support = \"clamped\"")) != std::string::npos;) {
    text.replace(at, 19, "support = [\"uy\"]");
  }
  ExpectContains(error(text),
                 "loose.toml: structure.nodes: nodes \"a0\", \"c0\", \"a1\", \"c1\" and 4 more "
                 "(with 4 beams, the body \"plate\") float: the supports at \"a0\", \"a1\", "
                 "\"a2\" and \"a3\" leave them a rigid motion, a translation along [1, 0, 0] (fix "
                 "more of the dofs");

  text = Plate();
  for (std::size_t at; (at = text.find("support = \"clamped\"\n")) != std::string::npos;) {
    text.replace(at, 20, "");
  }
  ExpectContains(error(text),
                 "structure.nodes: nodes \"a0\", \"c0\", \"a1\", \"c1\" and 4 more "
                 "(with 4 beams, the body \"plate\") float: no support holds them");

  // A beam beside the held plate, and a node on its own with a pin that leaves it turning.
  const std::string loose_beam =
      "\n[[structure.nodes]]\nname = \"x\"\nposition = [0.0, 50e-6, 0.0]\n"
      "\n[[structure.nodes]]\nname = \"y\"\nposition = [0.0, 50e-6, 80e-6]\n"
      "\n[[structure.beams]]\nnodes = [\"x\", \"y\"]\nwidth = 2e-6\nmaterial = \"poly\"\n";
  ExpectContains(
      error(Plate(loose_beam)),
      "structure.nodes: nodes \"x\" and \"y\" (with 1 beam) float: no support holds them "
      "(give one of them a support");
  ExpectContains(error(Plate("\n[[structure.nodes]]\nname = \"pin\"\nposition = [0.0, 0.0, "
                             "90e-6]\nsupport = \"pinned\"\n")),
                 "structure.nodes: node \"pin\" floats: the support at \"pin\" leaves it a rigid "
                 "motion, a rotation about [0, 1, 0]");
}

}  // namespace
}  // namespace cosmems
