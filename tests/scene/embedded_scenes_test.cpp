#include "cosmems/scene/embedded_scenes.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "cosmems/scene/scene_loader.hpp"
#include "scene_expectations.hpp"

namespace cosmems {
namespace {

std::string ShippedFile(std::string_view name) {
  return std::string(COSMEMS_SCENES_DIR) + "/" + std::string(name) + ".toml";
}

TEST(EmbeddedScenesTest, ListsTheShippedScenesInNameOrder) {
  const std::vector<EmbeddedScene>& scenes = EmbeddedScenes();
  ASSERT_GE(scenes.size(), 2u);
  for (std::size_t i = 1; i < scenes.size(); ++i) EXPECT_LT(scenes[i - 1].name, scenes[i].name);
  EXPECT_NE(FindEmbeddedScene("cantilever"), nullptr);
  EXPECT_NE(FindEmbeddedScene("microbridge"), nullptr);
  EXPECT_NE(FindEmbeddedScene("cantilever-release"), nullptr);
  EXPECT_EQ(FindEmbeddedScene("no-such-scene"), nullptr);
}

TEST(EmbeddedScenesTest, EachHasAOneLineDescriptionFromItsFirstComment) {
  for (const EmbeddedScene& scene : EmbeddedScenes()) {
    SCOPED_TRACE(std::string(scene.name));
    EXPECT_FALSE(scene.description.empty());
    EXPECT_EQ(scene.description.find('\n'), std::string_view::npos);
    EXPECT_EQ(scene.toml.substr(0, scene.description.size() + 2),
              "# " + std::string(scene.description));
  }
}

TEST(EmbeddedScenesTest, EachIsTheShippedFileAndLoadsAsAFileToo) {
  for (const EmbeddedScene& scene : EmbeddedScenes()) {
    SCOPED_TRACE(std::string(scene.name));
    std::ifstream file(ShippedFile(scene.name));
    ASSERT_TRUE(file) << ShippedFile(scene.name);
    std::ostringstream text;
    text << file.rdbuf();
    EXPECT_EQ(text.str(), scene.toml);
    const Scene embedded = LoadScene(std::string(scene.name));
    EXPECT_EQ(embedded.source, scene.name);
    testing::ExpectSameScene(LoadSceneFile(ShippedFile(scene.name)), embedded);
  }
}

TEST(EmbeddedScenesTest, CantileverIsTheDocumentedSiliconBeam) {
  const Scene scene = LoadScene("cantilever");
  EXPECT_EQ(scene.structure.kind, StructureKind::kCantilever);
  EXPECT_EQ(scene.structure.length, 200e-6);
  EXPECT_EQ(scene.structure.width, 20e-6);
  EXPECT_EQ(scene.structure.thickness, 2e-6);
  EXPECT_EQ(scene.structure.gap, 2e-6);
  EXPECT_EQ(scene.structure.axial_load, 0.0);
  EXPECT_EQ(scene.material.young_modulus, 169e9);
  EXPECT_EQ(scene.material.density, 2330.0);
  EXPECT_EQ(scene.material.poisson_ratio, 0.22);
  EXPECT_FALSE(scene.material.plate_modulus);
  EXPECT_EQ(scene.model.theory, Theory::kLinear);
  EXPECT_EQ(scene.model.dimension, 3);
  EXPECT_EQ(scene.model.elements, 20);
  EXPECT_EQ(scene.model.series_order, 1);
  EXPECT_EQ(scene.model.modes, 0);
  EXPECT_EQ(scene.loads.tip_force, Eigen::Vector3d(0.0, -1e-7, 0.0));
  EXPECT_EQ(scene.loads.tip_moment, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.loads.midspan_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.loads.distributed, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.analysis.type, AnalysisType::kStatic);
}

TEST(EmbeddedScenesTest, MicrobridgeIsTheDocumentedClampedClampedBeam) {
  const Scene scene = LoadScene("microbridge");
  EXPECT_EQ(scene.structure.kind, StructureKind::kBridge);
  EXPECT_EQ(scene.structure.length, 100e-6);
  EXPECT_EQ(scene.structure.width, 20e-6);
  EXPECT_EQ(scene.structure.thickness, 2e-6);
  EXPECT_EQ(scene.structure.gap, 4e-6);
  EXPECT_EQ(scene.material.young_modulus, 169e9);
  EXPECT_EQ(scene.material.density, 2330.0);
  EXPECT_EQ(scene.material.poisson_ratio, 0.22);
  EXPECT_EQ(scene.loads.midspan_force, Eigen::Vector3d(0.0, -1e-5, 0.0));
  EXPECT_EQ(scene.loads.tip_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.model.dimension, 3);
  EXPECT_EQ(scene.model.elements, 20);
  EXPECT_EQ(scene.model.series_order, 1);
  EXPECT_EQ(scene.analysis.type, AnalysisType::kStatic);
}

TEST(EmbeddedScenesTest, CantileverModalIsTheCantileverAskingForFourModes) {
  const Scene modal = LoadScene("cantilever-modal");
  EXPECT_EQ(modal.analysis.type, AnalysisType::kModal);
  EXPECT_EQ(modal.analysis.count, 4);
  Scene expected = LoadScene("cantilever", {SceneOverride::Parse("analysis.type=modal")});
  expected.loads = SceneLoads{};
  testing::ExpectSameScene(modal, expected);
}

TEST(EmbeddedScenesTest, CantileverReleaseLetsThePlanarCantileverGoFromItsStaticDeflection) {
  const Scene release = LoadScene("cantilever-release");
  EXPECT_EQ(release.analysis.type, AnalysisType::kTransient);
  EXPECT_EQ(release.analysis.duration, 1e-3);
  EXPECT_EQ(release.analysis.time_step, 1e-6);
  EXPECT_EQ(release.analysis.integrator, Integrator::kModal);
  EXPECT_EQ(release.analysis.initial, InitialState::kStatic);
  EXPECT_EQ(release.model.modes, 4);
  EXPECT_EQ(release.model.dimension, 2);
  EXPECT_FALSE(release.loads.time_function.has_value());
  ASSERT_TRUE(release.effects.damping.has_value());
  EXPECT_TRUE(release.effects.damping->enabled);
  EXPECT_EQ(release.effects.damping->quality_factor, 100.0);
  // Otherwise the reference cantilever, tip force and all.
  Scene expected =
      LoadScene("cantilever",
                {SceneOverride::Parse("model.dimension=2"), SceneOverride::Parse("model.modes=4"),
                 SceneOverride::Parse("effects.damping.quality_factor=100.0"),
                 SceneOverride::Parse("analysis.type=transient"),
                 SceneOverride::Parse("analysis.duration=1e-3"),
                 SceneOverride::Parse("analysis.time_step=1e-6"),
                 SceneOverride::Parse("analysis.integrator=modal"),
                 SceneOverride::Parse("analysis.initial=static")});
  testing::ExpectSameScene(release, expected);
}

}  // namespace
}  // namespace cosmems
