// The headless viewer's last frame, read back with an independent PNG reader: its size, the beam
// or the device and the substrate where the display's camera puts them, and the figures it
// reported.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <fstream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "device_stage.hpp"
#include "stage.hpp"
#include "viewport.hpp"

namespace cosmems::viewer {
namespace {

struct Image {
  int width = 0, height = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};

  // The pixel's channels, 0 to 255.
  Eigen::Vector3i At(const Eigen::Vector2d& p) const {
    const int x = static_cast<int>(p.x()), y = static_cast<int>(p.y());
    const unsigned char* c = pixels.get() + 3 * (static_cast<std::size_t>(y) * width + x);
    return Eigen::Vector3i(c[0], c[1], c[2]);
  }
};

Image Read(const std::string& path) {
  Image image;
  int channels = 0;
  image.pixels.reset(stbi_load(path.c_str(), &image.width, &image.height, &channels, 3));
  return image;
}

// Shading scales the three channels of a flat colour alike, so the hue tells the parts apart:
// the beam is orange (red over green over blue), the substrate blue.
bool LooksLikeBeam(const Eigen::Vector3i& c) {
  return c[0] > 80 && c[0] > 1.5 * c[1] && c[1] > 1.5 * c[2];
}
bool LooksLikeSubstrate(const Eigen::Vector3i& c) {
  return c[2] > 80 && c[2] > 1.4 * c[1] && c[1] > 1.2 * c[0];
}
// The electrode gold (red and green over blue), the supports grey (three channels alike).
bool LooksLikeElectrode(const Eigen::Vector3i& c) {
  return c[0] > 80 && c[1] > 0.7 * c[0] && c[1] > 2.0 * c[2];
}
bool LooksLikeSupport(const Eigen::Vector3i& c) {
  return c[0] > 60 && c.maxCoeff() < 1.15 * c.minCoeff();
}

// The figures a headless run printed (OUT_PREFIX.json); null when there are none.
nlohmann::json Figures(const std::string& output) {
  std::ifstream in(output + ".json");
  return in ? nlohmann::json::parse(in) : nlohmann::json();
}

class HeadlessViewerTest : public ::testing::Test {
 protected:
  void SetUp() override { Open(COSMEMS_VIEWER_OUTPUT, {}); }

  void Open(const std::string& output, const std::vector<SceneOverride>& overrides,
            const std::string& scene = "cantilever-haptic") {
    image_ = Read(output + ".png");
    ASSERT_NE(image_.pixels, nullptr) << "no screenshot at " << output << ".png";
    std::vector<SceneOverride> all = {{"analysis.type", "\"haptic\""}};
    all.insert(all.end(), overrides.begin(), overrides.end());
    scene_ = LoadScene(scene, all);
  }

  // Where the display's camera puts a point of the beam's axes [m].
  Eigen::Vector2d Pixel(const Eigen::Vector3d& micro_m) const {
    const DisplaySpace space;
    Eigen::Vector2d pixel;
    EXPECT_TRUE(
        DefaultCamera(scene_, space)
            .Project(space.ToWorld(micro_m), SceneViewport(image_.width, image_.height), pixel));
    EXPECT_GE(pixel.x(), kPanelWidth);
    EXPECT_LT(pixel.x(), image_.width);
    EXPECT_GE(pixel.y(), 0.0);
    EXPECT_LT(pixel.y(), image_.height);
    return pixel;
  }

  Image image_;
  Scene scene_;
};

TEST_F(HeadlessViewerTest, TheScreenshotHasTheWindowsSize) {
  EXPECT_EQ(image_.width, 1280);
  EXPECT_EQ(image_.height, 800);
}

// The upper face near the clamp, where the press at the tip moves it by less than 0.1 um.
TEST_F(HeadlessViewerTest, TheBeamIsWhereTheCameraPutsIt) {
  const double length = scene_.structure.length, top = 0.5 * scene_.structure.thickness;
  for (double x : {0.1, 0.2, 0.3}) {
    const Eigen::Vector2d pixel = Pixel(Eigen::Vector3d(x * length, top, 0.0));
    const Eigen::Vector3i colour = image_.At(pixel);
    EXPECT_TRUE(LooksLikeBeam(colour))
        << "x = " << x << " L at pixel " << pixel.transpose() << ": colour " << colour.transpose();
  }
}

// The substrate's top in front of the beam (which is 20 um wide: |z| <= 10 um), where nothing
// stands between it and the eye.
TEST_F(HeadlessViewerTest, TheSubstrateIsWhereTheCameraPutsIt) {
  const double length = scene_.structure.length;
  const double top = -0.5 * scene_.structure.thickness - *scene_.structure.gap;
  for (double x : {0.2, 0.5, 0.8}) {
    const Eigen::Vector2d pixel = Pixel(Eigen::Vector3d(x * length, top, 35e-6));
    const Eigen::Vector3i colour = image_.At(pixel);
    EXPECT_TRUE(LooksLikeSubstrate(colour))
        << "x = " << x << " L at pixel " << pixel.transpose() << ": colour " << colour.transpose();
  }
}

// The 120 um beam after the first press, stuck by its tip (arc-shaped, doc/surface.md): the
// figures say so, and the front face near the tip is drawn where the tip-loaded cantilever with
// its tip on the contact plane puts it, w = -g x^2 (3L - x) / (2 L^3), 1.6 - 1.8 um down at 0.9 -
// 0.95 L: there a free beam's face would stand 0.6 um and more above (3 um and more on the screen,
// at the display's vertical scale 5), and the substrate would show instead.
class HeadlessArcViewerTest : public HeadlessViewerTest {
 protected:
  void SetUp() override { Open(COSMEMS_VIEWER_ARC_OUTPUT, {{"structure.length", "120e-6"}}); }
};

TEST_F(HeadlessArcViewerTest, TheBeamStuckByItsTipIsDrawnBentOntoTheSubstrate) {
  const nlohmann::json json = Figures(COSMEMS_VIEWER_ARC_OUTPUT);
  ASSERT_FALSE(json.is_null()) << "no figures at " COSMEMS_VIEWER_ARC_OUTPUT ".json";
  EXPECT_EQ(json["contact_state"], "stuck");
  EXPECT_EQ(json["contact_shape"], "arc");
  const double length = scene_.structure.length;
  const double g = *scene_.structure.gap - scene_.effects.contact->separation.value_or(0.0);
  for (double x : {0.9, 0.95}) {
    const double w = -g * x * x * (3.0 - x) / 2.0;
    const Eigen::Vector2d pixel =
        Pixel(Eigen::Vector3d(x * length, w, 0.5 * scene_.structure.width));
    const Eigen::Vector3i colour = image_.At(pixel);
    EXPECT_TRUE(LooksLikeBeam(colour))
        << "x = " << x << " L at pixel " << pixel.transpose() << ": colour " << colour.transpose();
  }
}

// The plate on four serpentine springs, pressed onto the substrate by the stylus a second into the
// press, with contact (Viewer.HeadlessDeviceRun). Its electrode is a pad under exactly the
// plate's footprint: at rest, 2 um under the plate's lower face (10 um on the screen), the pad
// shows under the plate's near edge, as far in as the view reaches under it at the camera's pitch
// (0.5 rad: 18 um); lying on the substrate the plate hides it, and a point 3 um inside the near
// edge on the pad shows the plate's side face. The anchors stand where the netlist puts them,
// the substrate beyond the footprint.
class HeadlessDeviceViewerTest : public HeadlessViewerTest {
 protected:
  void SetUp() override {
    Open(COSMEMS_VIEWER_DEVICE_OUTPUT,
         {{"effects.contact.enabled", "true"}, {"effects.electrostatic.voltage", "2.0"}},
         "serpentine-pullin");
  }
};

TEST_F(HeadlessDeviceViewerTest, ThePlateLyingOnTheSubstrateHidesItsElectrode) {
  const nlohmann::json json = Figures(COSMEMS_VIEWER_DEVICE_OUTPUT);
  ASSERT_FALSE(json.is_null()) << "no figures at " COSMEMS_VIEWER_DEVICE_OUTPUT ".json";
  EXPECT_EQ(json["scene"], "serpentine-pullin");
  EXPECT_EQ(json["contact_state"], "contact");
  EXPECT_EQ(json["physics"]["failed_ticks"], 0);
  const DisplaySpace space;
  const OrbitCamera camera = DefaultCamera(scene_, space);
  const double pad = -1e-6 - *scene_.structure.gap + 0.02 * *scene_.structure.gap;
  // The edge of the footprint nearest the eye, and a point 3 um inside it on the pad.
  Eigen::Vector3d nearest = Eigen::Vector3d::Zero(), inward = Eigen::Vector3d::Zero();
  double closest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& edge :
       {Eigen::Vector3d(50e-6, pad, 0.0), Eigen::Vector3d(-50e-6, pad, 0.0),
        Eigen::Vector3d(0.0, pad, 50e-6), Eigen::Vector3d(0.0, pad, -50e-6)}) {
    const double distance = (space.ToWorld(edge) - camera.Eye()).norm();
    if (distance < closest) {
      closest = distance;
      nearest = edge;
      inward = -edge.normalized();
    }
  }
  for (double along : {-25e-6, 25e-6}) {
    const Eigen::Vector3d side(inward.z(), 0.0, -inward.x());
    const Eigen::Vector2d pixel = Pixel(nearest + 3e-6 * inward + along * side);
    const Eigen::Vector3i colour = image_.At(pixel);
    EXPECT_TRUE(LooksLikeBeam(colour))
        << "at pixel " << pixel.transpose() << ": colour " << colour.transpose();
    EXPECT_FALSE(LooksLikeElectrode(colour));
  }
}

TEST_F(HeadlessDeviceViewerTest, TheAnchorsAndTheSubstrateAreWhereTheCameraPutsThem) {
  const StructureDescription structure = MakeStructureDescription(scene_);
  int anchors = 0;
  for (const StructureNode& node : structure.nodes) {
    if (node.anchor != AnchorOf(Support::kClamped)) continue;
    ++anchors;
    // The anchor's top (12 um square) at its four quarter points: the spring ending on it covers
    // one side of it at most.
    int grey = 0;
    for (const Eigen::Vector3d& quarter :
         {Eigen::Vector3d(3e-6, 1e-6, 3e-6), Eigen::Vector3d(-3e-6, 1e-6, 3e-6),
          Eigen::Vector3d(3e-6, 1e-6, -3e-6), Eigen::Vector3d(-3e-6, 1e-6, -3e-6)}) {
      grey += LooksLikeSupport(image_.At(Pixel(node.position + quarter)));
    }
    EXPECT_GE(grey, 2) << node.name;
  }
  EXPECT_EQ(anchors, 4);
  // Beyond the footprint's corner, inside the substrate's margin.
  const Footprint f = FootprintOf(structure);
  const double top = f.lowest_face_m - *scene_.structure.gap;
  const Eigen::Vector2d pixel = Pixel({f.high.x() + 0.05 * f.Extent(), top, 0.0});
  EXPECT_TRUE(LooksLikeSubstrate(image_.At(pixel))) << image_.At(pixel).transpose();
}

// The figures are reported (the rates are measured, never asserted here: the machine decides
// them), with the scripted press's events.
TEST(HeadlessViewerFiguresTest, TheRunReportsItsDisplayAndServoFigures) {
  const nlohmann::json json = Figures(COSMEMS_VIEWER_OUTPUT);
  ASSERT_FALSE(json.is_null()) << "no figures at " COSMEMS_VIEWER_OUTPUT ".json";
  EXPECT_EQ(json["frames"], COSMEMS_VIEWER_FRAMES);
  EXPECT_EQ(json["input"], "script");
  EXPECT_GT(json["display_rate_hz"].get<double>(), 0.0);
  EXPECT_GT(json["servo"]["ticks"].get<long>(), 0);
  EXPECT_GT(json["servo"]["rate_hz"].get<double>(), 0.0);
  EXPECT_GT(json["physics"]["ticks"].get<long>(), 0);
  EXPECT_EQ(json["physics"]["failed_ticks"], 0);
  EXPECT_EQ(json["window"], nlohmann::json::array({1280, 800}));
}

}  // namespace
}  // namespace cosmems::viewer
