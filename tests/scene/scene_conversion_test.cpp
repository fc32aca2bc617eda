#include "cosmems/scene/scene_conversion.hpp"

#include <gtest/gtest.h>

#include "cosmems/scene/scene_loader.hpp"

namespace cosmems {
namespace {

Scene Load(const std::string& name, const std::vector<std::string>& assignments = {}) {
  std::vector<SceneOverride> overrides;
  for (const std::string& a : assignments) overrides.push_back(SceneOverride::Parse(a));
  return LoadScene(name, overrides);
}

TEST(SceneConversionTest, CantileverIsClampedAtTheRootOnly) {
  const Scene scene = Load("cantilever", {"model.elements=8", "model.series_order=2"});
  const BeamDescription beam = MakeBeamDescription(scene);
  ASSERT_EQ(beam.elements.size(), 8u);
  EXPECT_DOUBLE_EQ(beam.Length(), 200e-6);
  EXPECT_EQ(beam.series_order, 2);
  EXPECT_EQ(beam.supports.front(), Support::kClamped);
  EXPECT_EQ(beam.supports.back(), Support::kFree);
  for (const ElementSpec& element : beam.elements) {
    EXPECT_EQ(element.section.width, 20e-6);
    EXPECT_EQ(element.section.thickness, 2e-6);
    EXPECT_EQ(element.material.young_modulus, 169e9);
    EXPECT_EQ(element.material.density, 2330.0);
    EXPECT_EQ(element.material.poisson_ratio, 0.22);
  }
}

TEST(SceneConversionTest, BridgeIsClampedAtBothEnds) {
  const BeamDescription beam = MakeBeamDescription(Load("microbridge"));
  EXPECT_EQ(beam.supports.front(), Support::kClamped);
  EXPECT_EQ(beam.supports.back(), Support::kClamped);
  for (std::size_t n = 1; n + 1 < beam.supports.size(); ++n) {
    EXPECT_EQ(beam.supports[n], Support::kFree);
  }
}

TEST(SceneConversionTest, PlateModulusDividesByOneMinusNuSquared) {
  SceneMaterial material;
  material.young_modulus = 169e9;
  material.density = 2330.0;
  material.poisson_ratio = 0.28;
  EXPECT_EQ(EffectiveMaterial(material).young_modulus, 169e9);
  material.plate_modulus = true;
  EXPECT_DOUBLE_EQ(EffectiveMaterial(material).young_modulus, 169e9 / (1.0 - 0.28 * 0.28));
  EXPECT_EQ(EffectiveMaterial(material).density, 2330.0);
  EXPECT_EQ(EffectiveMaterial(material).poisson_ratio, 0.28);
}

TEST(SceneConversionTest, TipLoadsActAtTheFreeEnd) {
  const LoadCase loads = MakeLoadCase(Load("cantilever", {"loads.tip_moment=[0, 0, 1e-12]"}));
  ASSERT_EQ(loads.points.size(), 1u);
  EXPECT_EQ(loads.points[0].x, 200e-6);
  EXPECT_EQ(loads.points[0].force, Eigen::Vector3d(0.0, -1e-7, 0.0));
  EXPECT_EQ(loads.points[0].moment, Eigen::Vector3d(0.0, 0.0, 1e-12));
  EXPECT_EQ(loads.distributed, Eigen::Vector3d::Zero());
}

TEST(SceneConversionTest, MidspanAndDistributedLoadsOnABridge) {
  const LoadCase loads = MakeLoadCase(Load("microbridge", {"loads.distributed=[0, -2.0, 0]"}));
  ASSERT_EQ(loads.points.size(), 1u);
  EXPECT_EQ(loads.points[0].x, 50e-6);
  EXPECT_EQ(loads.points[0].force, Eigen::Vector3d(0.0, -1e-5, 0.0));
  EXPECT_EQ(loads.points[0].moment, Eigen::Vector3d::Zero());
  EXPECT_EQ(loads.distributed, Eigen::Vector3d(0.0, -2.0, 0.0));
}

TEST(SceneConversionTest, LeavesOutZeroLoads) {
  const LoadCase loads = MakeLoadCase(Load("cantilever", {"loads.tip_force=[0, 0, 0]"}));
  EXPECT_TRUE(loads.points.empty());
}

}  // namespace
}  // namespace cosmems
