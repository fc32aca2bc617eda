// The viewer's parts that need no display: the camera's projection against its own ray, the
// structure's mesh and the plotted point against the shapes they draw, and the panel's settings
// against the scene loader.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "camera.hpp"
#include "comb_mesh.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/scene_error.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "device_mesh.hpp"
#include "model_settings.hpp"

namespace cosmems::viewer {
namespace {

// Vertex v's position: the mesh's floats from 6 v.
Eigen::Vector3d Vertex(const Mesh& mesh, int v) {
  return Eigen::Map<const Eigen::Vector3f>(&mesh.vertices[6 * v]).cast<double>();
}

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

// A hexahedron's six faces of two triangles: 36 vertices, its upper face (corners 2, 6, 7, 3:
// a, b, c, a, c, d) from the 18th.
constexpr int kHexahedron = 36, kUpperFace = 18;

// A member along x, 200 x 20 x 2 um, clamped at x = 0 and moved as a cantilever under a tip force
// (a cubic the element's Hermite cubics hold exactly): w = w_L x^2 (3L - x) / (2 L^3), slope
// theta_z = w'. Each sample's upper edge lies where the section turned by the slope puts it,
// (x - (t/2) sin theta, w + (t/2) cos theta), to the precision of the mesh's floats.
TEST(DeviceMeshTest, AMemberIsDrawnOnItsHermiteShapeWithItsSectionsTurned) {
  StructureDescription s;
  s.nodes = {{"clamp", {0.0, 0.0, 0.0}, AnchorOf(Support::kClamped)},
             {"tip", {200e-6, 0.0, 0.0}, {}}};
  StructureMember member;
  member.from = 0;
  member.to = 1;
  member.section = {20e-6, 2e-6};
  member.elements = 5;
  s.members = {member};
  const FrameMesh mesh(s);
  const double length = 200e-6, tip_w = -1.5e-6, l3 = length * length * length;
  auto w = [&](double x) { return tip_w * x * x * (3 * length - x) / (2 * l3); };
  auto slope = [&](double x) { return 3 * tip_w * x * (2 * length - x) / (2 * l3); };
  HapticFrame frame;
  frame.carrier_motion_m.setZero(6, static_cast<Eigen::Index>(mesh.carriers.size()));
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n) {
    const double x = mesh.nodes[n].position.x();
    frame.carrier_motion_m(1, mesh.nodes[n].carrier) = w(x);
    frame.carrier_motion_m(5, mesh.nodes[n].carrier) = slope(x);
  }
  const DisplaySpace space{5.0};
  Mesh members, bodies;
  const int samples = 3;
  BuildDeviceMesh(frame, mesh, s, space, members, bodies, samples);
  ASSERT_EQ(members.VertexCount(), 5 * samples * kHexahedron);
  EXPECT_EQ(bodies.VertexCount(), 0);
  for (int segment = 0; segment < 5 * samples; ++segment) {
    // Corners 2 and 6 of the upper face: the upper edge's two ends at the segment's start.
    const int first = segment * kHexahedron + kUpperFace;
    const Eigen::Vector3d edge =
        space.ToMicro(0.5 * (Vertex(members, first) + Vertex(members, first + 1)));
    const double x = length * segment / (5.0 * samples), theta = slope(x);
    // Floats hold 200 um to 2e-11 m; a chord between the nodes would miss w by 1e-8 m.
    EXPECT_NEAR(edge.x(), x - 1e-6 * std::sin(theta), 1e-10) << "segment " << segment;
    EXPECT_NEAR(edge.y(), w(x) + 1e-6 * std::cos(theta), 1e-11) << "segment " << segment;
    EXPECT_NEAR(edge.z(), 0.0, 1e-11);
  }
  // The plotted point between nodes (a bridge's midspan on an odd count of elements) is on the
  // same cubic: 1e-18 m, doubles' round-off on micrometres.
  for (const double xi : {0.0, 0.3, 0.5, 1.0}) {
    const Eigen::Vector3d u = ElementPointMotion(frame, mesh, 2, xi);
    EXPECT_NEAR(u.y(), w(length * (2.0 + xi) / 5.0), 1e-18) << xi;
    EXPECT_NEAR(u.x(), 0.0, 1e-18) << xi;
  }
}

// The plate of the serpentine scene moved rigidly (down, and turned about x and z): every corner
// of its block where the exact rotation about its centre puts it.
TEST(DeviceMeshTest, ABodyIsItsBlockMovedRigidly) {
  const Scene scene = LoadScene("serpentine", {});
  const StructureDescription s = MakeStructureDescription(scene);
  const FrameMesh mesh(s);
  HapticFrame frame;
  frame.carrier_motion_m.setZero(6, static_cast<Eigen::Index>(mesh.carriers.size()));
  Eigen::Matrix<double, 6, 1> q;
  q << 0.2e-6, -0.5e-6, 0.1e-6, 0.01, 0.0, -0.02;
  frame.carrier_motion_m.col(mesh.body_carrier[0]) = q;
  const DisplaySpace space{5.0};
  Mesh members, bodies;
  BuildDeviceMesh(frame, mesh, s, space, members, bodies);
  ASSERT_EQ(bodies.VertexCount(), kHexahedron);
  const StructureBody& plate = s.bodies[0];
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(q.tail<3>().norm(), q.tail<3>().normalized()).toRotationMatrix();
  for (int v = 0; v < kHexahedron; ++v) {
    const Eigen::Vector3d p =
        r.transpose() * (space.ToMicro(Vertex(bodies, v)) - plate.center - q.head<3>());
    // Back in the plate's own axes, every corner is at half its size from the centre.
    EXPECT_TRUE(p.cwiseAbs().isApprox(0.5 * plate.size, 1e-6)) << p.transpose();
  }
}

// A comb of 20 fingers: the moving half 20 fingers on the body's +x face moving with it, the
// fixed half 21 fingers and their spine, interleaved with the moving ones `overlap` deep.
TEST(CombMeshTest, TheFingersInterleaveOverTheOverlap) {
  const Scene scene = LoadScene("comb-drive", {});
  const StructureDescription s = MakeStructureDescription(scene);
  const CombDrive comb = MakeCombDrives(scene, s).at(0);
  const StructureBody& shuttle = s.bodies[comb.body];
  const DisplaySpace space{1.0};
  Mesh moving, fixed;
  Eigen::Matrix<double, 6, 1> q = Eigen::Matrix<double, 6, 1>::Zero();
  AddCombFingers(comb, shuttle, CombHalf::kFixed, q, space, fixed);
  AddCombFingers(comb, shuttle, CombHalf::kMoving, q, space, moving);
  ASSERT_EQ(moving.VertexCount(), comb.fingers * kHexahedron);
  ASSERT_EQ(fixed.VertexCount(), (comb.fingers + 2) * kHexahedron);
  auto reach = [&](const Mesh& mesh, int finger, bool far) {
    double x = far ? -1e300 : 1e300;
    for (int v = finger * kHexahedron; v < (finger + 1) * kHexahedron; ++v) {
      x = far ? std::max(x, Vertex(mesh, v).x()) : std::min(x, Vertex(mesh, v).x());
    }
    return 1e-6 * x;
  };
  const double face = shuttle.center.x() + 0.5 * shuttle.size.x();
  // Floats hold 60 um to 1e-11 m.
  EXPECT_NEAR(reach(moving, 0, false), face, 1e-10);
  // The moving tips stand `overlap` past the fixed tips.
  EXPECT_NEAR(reach(moving, 0, true) - reach(fixed, 0, false), comb.overlap, 1e-10);
  // Moved 1 um along the comb, the moving half follows, the fixed half stays.
  q[0] = 1e-6;
  Mesh moved;
  AddCombFingers(comb, shuttle, CombHalf::kMoving, q, space, moved);
  EXPECT_NEAR(reach(moved, 0, true) - reach(moving, 0, true), 1e-6, 1e-10);
}

// A parametric device's design keys and its contact and stiction are edited and read back through
// the loader; the beam's sizes, which a device refuses, are not written.
TEST(ModelSettingsTest, ADevicesDesignKeysReadBackThroughTheLoader) {
  const std::vector<SceneOverride> haptic = {{"analysis.type", "\"haptic\""}};
  const Scene scene = LoadScene("serpentine-pullin", haptic);
  ModelSettings settings = ModelSettings::FromScene(scene, HapticPhysicsOptions{});
  ASSERT_EQ(settings.design.size(), 6u);
  EXPECT_EQ(settings.design[0].key, "beam_width");
  for (DesignParameter& p : settings.design) {
    if (p.key == "turns") p.value = 6;
    if (p.key == "span_length") p.value = 60e-6;
  }
  settings.contact = true;
  settings.stiction = true;
  settings.adhesion_energy_j_m2 = 1e-3;
  std::vector<SceneOverride> overrides = haptic;
  for (const SceneOverride& o : settings.ToOverrides()) overrides.push_back(o);
  const Scene edited = LoadScene("serpentine-pullin", overrides);
  EXPECT_EQ(edited.structure.serpentine.turns, 6);
  EXPECT_EQ(edited.structure.serpentine.span_length, 60e-6);
  EXPECT_EQ(edited.structure.serpentine.plate_width, scene.structure.serpentine.plate_width);
  EXPECT_EQ(edited.structure.gap, scene.structure.gap);
  EXPECT_TRUE(IsOn(edited.effects.contact));
  ASSERT_TRUE(IsOn(edited.effects.stiction));
  EXPECT_EQ(*edited.effects.stiction->adhesion_energy, 1e-3);
  EXPECT_EQ(ModelSettings::FromScene(edited, HapticPhysicsOptions{}).ToOverrides().size(),
            settings.ToOverrides().size());
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
