// The viewer's parts that need no display: the camera's projection against its own ray, the beam
// mesh against the frame it draws, and the panel's settings against the scene loader.
#include <gtest/gtest.h>

#include <limits>

#include "beam_mesh.hpp"
#include "camera.hpp"
#include "cosmems/scene/scene_error.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "model_settings.hpp"

namespace cosmems::viewer {
namespace {

TEST(OrbitCameraTest, APixelsRayPassesThroughThePointsThatProjectOntoIt) {
  OrbitCamera camera(Eigen::Vector3d(110.0, 0.0, 0.0), 320.0, 0.5, 0.3);
  camera.Orbit(40.0, -25.0);
  const Viewport viewport{380, 0, 900, 800};
  for (const Eigen::Vector3d& world :
       {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(200.0, -20.0, 35.0),
        Eigen::Vector3d(110.0, 40.0, -60.0)}) {
    Eigen::Vector2d pixel;
    ASSERT_TRUE(camera.Project(world, viewport, pixel));
    const Ray ray = camera.Unproject(pixel, viewport);
    const Eigen::Vector3d to_point = world - ray.origin;
    // The point's distance from the ray, relative to its distance from the eye.
    EXPECT_LT((to_point - to_point.dot(ray.direction) * ray.direction).norm(),
              1e-9 * to_point.norm());
  }
  // The target lands in the middle of the viewport.
  Eigen::Vector2d centre;
  ASSERT_TRUE(camera.Project(camera.target(), viewport, centre));
  EXPECT_NEAR(centre.x(), 380 + 450, 1e-9);
  EXPECT_NEAR(centre.y(), 400, 1e-9);
}

HapticFrame Frame(int nodes, double length, double tip_w) {
  HapticFrame frame;
  frame.node_x_m.setLinSpaced(nodes, 0.0, length);
  // A cantilever under a tip load: w = w_L x^2 (3L - x) / (2 L^3), theta = 3 w_L x (2L - x) / (2
  // L^3).
  frame.deflection_m.resize(nodes);
  frame.rotation_rad.resize(nodes);
  for (int k = 0; k < nodes; ++k) {
    const double x = frame.node_x_m[k], l3 = length * length * length;
    frame.deflection_m[k] = tip_w * x * x * (3 * length - x) / (2 * l3);
    frame.rotation_rad[k] = 3 * tip_w * x * (2 * length - x) / (2 * l3);
  }
  return frame;
}

TEST(BeamMeshTest, TheStraightBeamIsItsBox) {
  Mesh mesh;
  const DisplaySpace space{5.0};
  BuildBeamMesh(Frame(11, 200e-6, 0.0), 20e-6, 2e-6, space, mesh);
  // 10 elements of 4 samples, 4 faces of 2 triangles each, and the 2 end faces.
  EXPECT_EQ(mesh.VertexCount(), 40 * 4 * 6 + 2 * 6);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (int v = 0; v < mesh.VertexCount(); ++v) {
    const Eigen::Vector3d p(mesh.vertices[6 * v], mesh.vertices[6 * v + 1],
                            mesh.vertices[6 * v + 2]);
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  // um, the thickness stretched 5 times; float storage.
  EXPECT_TRUE(low.isApprox(Eigen::Vector3d(0.0, -5.0, -10.0), 1e-6));
  EXPECT_TRUE(high.isApprox(Eigen::Vector3d(200.0, 5.0, 10.0), 1e-6));
}

TEST(BeamMeshTest, TheEndFaceFollowsTheTipAndTurnsWithItsSlope) {
  Mesh mesh;
  const DisplaySpace space{5.0};
  const double tip_w = -2e-6;
  BuildBeamMesh(Frame(21, 200e-6, tip_w), 20e-6, 2e-6, space, mesh);
  // The last 6 vertices are the tip's end face; its centre is the deflected tip, its normal the
  // stretched tangent (1, 5 w'(L)) with w'(L) = 3 w_L / (2 L).
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  const int first = mesh.VertexCount() - 6;
  for (int v : {first, first + 1, first + 2, first + 4}) {  // the quad's four corners
    centre += 0.25 * Eigen::Vector3d(mesh.vertices[6 * v], mesh.vertices[6 * v + 1],
                                     mesh.vertices[6 * v + 2]);
  }
  EXPECT_NEAR(centre.x(), 200.0, 1e-4);
  EXPECT_NEAR(centre.y(), 5.0 * -2.0, 1e-4);
  const Eigen::Vector3d normal(mesh.vertices[6 * first + 3], mesh.vertices[6 * first + 4],
                               mesh.vertices[6 * first + 5]);
  const Eigen::Vector3d tangent =
      Eigen::Vector3d(1.0, 5.0 * 1.5 * tip_w / 200e-6, 0.0).normalized();
  EXPECT_TRUE(normal.isApprox(tangent, 1e-6));
}

TEST(ModelSettingsTest, ThePanelsSettingsReadBackAsTheSceneTheyCameFrom) {
  const std::vector<SceneOverride> haptic = {{"analysis.type", "\"haptic\""}};
  const Scene scene = LoadScene("cantilever-haptic", haptic);
  ModelSettings settings = ModelSettings::FromScene(scene, HapticPhysicsOptions{});
  settings.elements = 12;
  settings.young_modulus_pa = 150e9;
  settings.kind = StructureKind::kBridge;
  settings.van_der_waals = true;
  settings.hamaker_j = 2e-19;
  std::vector<SceneOverride> overrides = haptic;
  for (const SceneOverride& o : settings.ToOverrides()) overrides.push_back(o);
  const Scene edited = LoadScene("cantilever-haptic", overrides);
  EXPECT_EQ(edited.model.elements, 12);
  EXPECT_EQ(edited.material.young_modulus, 150e9);
  EXPECT_EQ(edited.structure.kind, StructureKind::kBridge);
  EXPECT_EQ(edited.structure.length, scene.structure.length);
  EXPECT_EQ(edited.structure.gap, scene.structure.gap);
  EXPECT_TRUE(IsOn(edited.effects.stiction));
  EXPECT_EQ(*edited.effects.stiction->adhesion_energy, 0.02);
  EXPECT_TRUE(IsOn(edited.effects.casimir));
  EXPECT_FALSE(IsOn(edited.effects.electrostatic));
  ASSERT_TRUE(IsOn(edited.effects.van_der_waals));
  EXPECT_EQ(*edited.effects.van_der_waals->hamaker, 2e-19);
  EXPECT_EQ(ModelSettings::FromScene(edited, HapticPhysicsOptions{}).ToOverrides().size(),
            settings.ToOverrides().size());
}

TEST(ModelSettingsTest, AnEditTheLoaderRefusesNamesTheKeyAndTheValue) {
  ModelSettings settings = ModelSettings::FromScene(
      LoadScene("cantilever-haptic", {{"analysis.type", "\"haptic\""}}), HapticPhysicsOptions{});
  settings.elements = 0;
  try {
    LoadScene("cantilever-haptic", settings.ToOverrides());
    FAIL() << "0 elements were accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("model.elements"), std::string::npos) << e.what();
  }
}

TEST(ModelSettingsTest, FloatsStayFloatsInToml) {
  EXPECT_EQ(TomlFloat(169e9), "169000000000.0");
  EXPECT_EQ(TomlFloat(2e-6), "1.9999999999999999e-06");
  EXPECT_EQ(TomlFloat(2330.0), "2330.0");
}

}  // namespace
}  // namespace cosmems::viewer
