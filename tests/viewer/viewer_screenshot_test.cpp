// The headless viewer's last frame, read back with an independent PNG reader: its size, the beam
// and the substrate where the display's camera puts them, and the figures it reported.
#include <gtest/gtest.h>
#include <stb_image.h>

#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cosmems/scene/scene_loader.hpp"
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

class HeadlessViewerTest : public ::testing::Test {
 protected:
  void SetUp() override { Open(COSMEMS_VIEWER_OUTPUT, {}); }

  void Open(const std::string& output, const std::vector<SceneOverride>& overrides) {
    image_ = Read(output + ".png");
    ASSERT_NE(image_.pixels, nullptr) << "no screenshot at " << output << ".png";
    std::vector<SceneOverride> all = {{"analysis.type", "\"haptic\""}};
    all.insert(all.end(), overrides.begin(), overrides.end());
    scene_ = LoadScene("cantilever-haptic", all);
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
  std::ifstream in(COSMEMS_VIEWER_ARC_OUTPUT ".json");
  ASSERT_TRUE(in) << "no figures at " COSMEMS_VIEWER_ARC_OUTPUT ".json";
  const nlohmann::json json = nlohmann::json::parse(in);
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

// The figures are reported (the rates are measured, never asserted here: the machine decides
// them), with the scripted press's events.
TEST(HeadlessViewerFiguresTest, TheRunReportsItsDisplayAndServoFigures) {
  std::ifstream in(COSMEMS_VIEWER_OUTPUT ".json");
  ASSERT_TRUE(in) << "no figures at " COSMEMS_VIEWER_OUTPUT ".json";
  const nlohmann::json json = nlohmann::json::parse(in);
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
