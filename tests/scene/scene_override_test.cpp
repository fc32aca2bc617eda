#include <gtest/gtest.h>

#include <string>

#include "cosmems/scene/scene_error.hpp"
#include "cosmems/scene/scene_loader.hpp"

namespace cosmems {
namespace {

Scene Cantilever(const std::vector<std::string>& assignments) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : assignments) {
    overrides.push_back(SceneOverride::Parse(assignment));
  }
  return LoadScene("cantilever", overrides);
}

std::string Message(const std::vector<std::string>& assignments) {
  try {
    Cantilever(assignments);
  } catch (const SceneError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no SceneError";
  return "";
}

TEST(SceneOverrideTest, SplitsAtTheFirstEqualsSign) {
  const SceneOverride o = SceneOverride::Parse(" device.trajectory = \"a=b.csv\" ");
  EXPECT_EQ(o.key, "device.trajectory");
  EXPECT_EQ(o.value, "\"a=b.csv\"");
  EXPECT_EQ(Cantilever({"analysis.type = modal"}).analysis.type, AnalysisType::kModal);
}

TEST(SceneOverrideTest, ReplacesValuesOfEveryType) {
  const Scene scene =
      Cantilever({"model.elements=8", "structure.length=150e-6", "material.plate_modulus=true",
                  "model.theory=\"linear\"", "loads.distributed=[0, -1e-3, 0]"});
  EXPECT_EQ(scene.model.elements, 8);
  EXPECT_EQ(scene.structure.length, 150e-6);
  EXPECT_TRUE(scene.material.plate_modulus);
  EXPECT_EQ(scene.loads.distributed, Eigen::Vector3d(0.0, -1e-3, 0.0));
  EXPECT_EQ(scene.source, "cantilever");
}

TEST(SceneOverrideTest, TakesABareWordAsAString) {
  EXPECT_EQ(Cantilever({"analysis.type=modal"}).analysis.type, AnalysisType::kModal);
  EXPECT_EQ(Cantilever({"analysis.type=\"modal\""}).analysis.type, AnalysisType::kModal);
  EXPECT_EQ(Cantilever({"structure.kind=bridge", "loads.tip_force=[0,0,0]"}).structure.kind,
            StructureKind::kBridge);
}

TEST(SceneOverrideTest, KeepsTomlKeywordsAsTheirTomlValues) {
  // true, inf and nan parse as TOML, so they are never taken as bare-word strings.
  EXPECT_TRUE(Cantilever({"material.plate_modulus=true"}).material.plate_modulus);
  EXPECT_EQ(Message({"structure.gap=inf"}), "--set: structure.gap = inf: must be finite");
}

TEST(SceneOverrideTest, CreatesMissingTables) {
  const Scene scene = Cantilever({"effects.casimir.enabled=false"});
  ASSERT_TRUE(scene.effects.casimir.has_value());
  EXPECT_FALSE(scene.effects.casimir->enabled);
  const Scene deep =
      Cantilever({"effects.electrostatic.enabled=false", "effects.electrostatic.voltage=12.5"});
  EXPECT_EQ(deep.effects.electrostatic->voltage, 12.5);
}

TEST(SceneOverrideTest, AcceptsAnInlineTable) {
  const Scene scene = Cantilever({"effects.stiction={ enabled = false, adhesion_energy = 0.05 }"});
  EXPECT_EQ(scene.effects.stiction->adhesion_energy, 0.05);
}

TEST(SceneOverrideTest, LaterOverridesWin) {
  EXPECT_EQ(Cantilever({"model.elements=8", "model.elements=12"}).model.elements, 12);
}

TEST(SceneOverrideTest, BlamesTheCommandLineForTheValuesItWrote) {
  EXPECT_EQ(Message({"model.elements=ten"}),
            "--set: model.elements = \"ten\": expected an integer");
  EXPECT_EQ(
      Message({"structure.lenght=1e-4"})
          .rfind("--set: structure.lenght = 1e-04: unknown key (expected kind, thickness,", 0),
      0u);
  EXPECT_EQ(
      Message({"effects.stiction.adhesion_energy=0.0"})
          .rfind("--set: effects.stiction.adhesion_energy = 0.0: needs the work of adhesion", 0),
      0u);
}

TEST(SceneOverrideTest, RefusesMalformedAssignments) {
  EXPECT_EQ(Message({"model.elements"}),
            "--set: model.elements: expected KEY=VALUE, such as model.elements=8");
  EXPECT_EQ(Message({"=8"}), "--set: =8: expected KEY=VALUE, such as model.elements=8");
  EXPECT_EQ(Message({"model..elements=8"}),
            "--set: model..elements = 8: KEY must be dotted bare keys, such as model.elements");
  EXPECT_EQ(Message({"model.elements=1e-6x"}),
            "--set: model.elements = 1e-6x: not a TOML value (strings take quotes: "
            "'KEY=\"text\"')");
  EXPECT_EQ(Message({"loads.tip_force=[0, -1e-7"})
                .rfind("--set: loads.tip_force = [0, -1e-7: not a TOML value", 0),
            0u);
}

TEST(SceneOverrideTest, RefusesAValueThatSmugglesInMoreKeys) {
  const std::string message = Message({"model.elements=8\n[device]"});
  EXPECT_EQ(message.rfind("--set: model.elements = 8\\n[device]: not a TOML value", 0), 0u)
      << message;
}

TEST(SceneOverrideTest, RefusesAPathThroughAValue) {
  EXPECT_EQ(Message({"loads.tip_force.y=1"}),
            "--set: loads.tip_force.y = 1: loads.tip_force = [0.0, -1e-07, 0.0] is not a table");
}

}  // namespace
}  // namespace cosmems
