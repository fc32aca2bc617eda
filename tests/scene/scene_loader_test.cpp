#include "cosmems/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cosmems/scene/scene_error.hpp"
#include "fifo_scene.hpp"

namespace cosmems {
namespace {

// Only the required keys.
constexpr const char* kMinimal = R"(
[structure]
kind = "cantilever"
length = 1e-4
width = 1e-5
thickness = 1e-6
[material]
young_modulus = 1.6e11
density = 2330
[analysis]
type = "static"
)";

std::string Message(const std::function<void()>& load) {
  try {
    load();
  } catch (const SceneError& error) {
    return error.what();
  }
  ADD_FAILURE() << "no SceneError";
  return "";
}

class TempFile {
 public:
  TempFile(const std::string& name, const std::string& text)
      : path_(std::filesystem::path(::testing::TempDir()) / name) {
    std::ofstream(path_) << text;
  }
  ~TempFile() { std::filesystem::remove(path_); }
  std::string path() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

TEST(SceneLoaderTest, MinimalSceneTakesEveryDocumentedDefault) {
  const Scene scene = LoadSceneText(kMinimal, "minimal.toml");
  EXPECT_EQ(scene.source, "minimal.toml");
  EXPECT_FALSE(scene.structure.gap.has_value());
  EXPECT_EQ(scene.structure.axial_load, 0.0);
  EXPECT_EQ(scene.material.density, 2330.0);  // a TOML integer is a number too
  EXPECT_EQ(scene.material.poisson_ratio, 0.22);
  EXPECT_FALSE(scene.material.plate_modulus);
  EXPECT_EQ(scene.model.theory, Theory::kLinear);
  EXPECT_EQ(scene.model.dimension, 3);
  EXPECT_EQ(scene.model.elements, 20);
  EXPECT_EQ(scene.model.series_order, 1);
  EXPECT_EQ(scene.model.modes, 0);
  EXPECT_EQ(scene.loads.tip_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.loads.midspan_force, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.loads.distributed, Eigen::Vector3d::Zero());
  EXPECT_EQ(scene.loads.tip_moment, Eigen::Vector3d::Zero());
  EXPECT_FALSE(scene.loads.time_function.has_value());
  EXPECT_FALSE(scene.effects.contact || scene.effects.stiction || scene.effects.electrostatic ||
               scene.effects.casimir || scene.effects.van_der_waals || scene.effects.damping);
  EXPECT_FALSE(scene.device.has_value());
}

TEST(SceneLoaderTest, ModalCountDefaultsToFour) {
  const Scene scene =
      LoadSceneText(kMinimal, "minimal.toml", {SceneOverride::Parse("analysis.type=modal")});
  EXPECT_EQ(scene.analysis.type, AnalysisType::kModal);
  EXPECT_EQ(scene.analysis.count, 4);
}

TEST(SceneLoaderTest, ReadsAFileByPathAndNamesItInErrors) {
  const TempFile good("good_scene.toml", kMinimal);
  EXPECT_EQ(LoadScene(good.path()).source, good.path());
  EXPECT_EQ(LoadSceneFile(good.path()).structure.length, 1e-4);

  const TempFile bad("bad_scene.toml", std::string(kMinimal) + "[model]\nelements = 0\n");
  EXPECT_EQ(Message([&] { LoadScene(bad.path()); }),
            bad.path() + ": model.elements = 0: must be at least 1");
}

TEST(SceneLoaderTest, RefusesAMissingFile) {
  const std::string message = Message([] { LoadScene("no/such/scene.toml"); });
  EXPECT_EQ(message.rfind("no/such/scene.toml: cannot open scene file", 0), 0u) << message;
}

TEST(SceneLoaderTest, RefusesADirectory) {
  const std::string directory = ::testing::TempDir();
  EXPECT_EQ(Message([&] { LoadSceneFile(directory); }),
            directory + ": is a directory, not a scene file");
}

// A FIFO or a device could be read without end: only regular files are read.
TEST(SceneLoaderTest, RefusesWhatIsNotARegularFile) {
  const std::string reason = ": not a regular file (a FIFO, socket or device), not a scene file";
  EXPECT_EQ(Message([] { LoadSceneFile("/dev/null"); }), "/dev/null" + reason);
  const testing::FifoScene fifo(std::filesystem::path(::testing::TempDir()) / "fifo_scene.toml",
                                kMinimal);
  EXPECT_EQ(Message([&] { LoadScene(fifo.path()); }), fifo.path() + reason);
}

// Scenes are a few hundred bytes: a file of 1 MiB is read, one byte more is refused by name.
TEST(SceneLoaderTest, RefusesAFileLargerThanOneMebibyte) {
  const std::size_t limit = std::size_t{1} << 20;
  std::string text = kMinimal;
  text += "#" + std::string(limit - text.size() - 2, 'x') + "\n";
  ASSERT_EQ(text.size(), limit);
  const TempFile largest("largest_scene.toml", text);
  EXPECT_EQ(LoadSceneFile(largest.path()).structure.length, 1e-4);
  const TempFile larger("larger_scene.toml", text + "\n");
  EXPECT_EQ(Message([&] { LoadSceneFile(larger.path()); }),
            larger.path() + ": larger than 1048576 bytes (1 MiB), the most a scene file may hold");
}

TEST(SceneLoaderTest, NamesTheEmbeddedScenesForAnUnknownName) {
  const std::string message = Message([] { LoadScene("cantilver"); });
  EXPECT_NE(message.find("cantilver: neither an embedded scene ("), std::string::npos) << message;
  EXPECT_NE(message.find("cantilever"), std::string::npos);
  EXPECT_NE(message.find("microbridge"), std::string::npos);
}

TEST(SceneLoaderTest, ReportsInvalidTomlWithItsPosition) {
  const std::string message =
      Message([] { LoadSceneText("[structure]\nlength = = 1\n", "x.toml"); });
  EXPECT_EQ(message.rfind("x.toml: invalid TOML at line 2, column ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
}

TEST(SceneLoaderTest, ParsesTheDocumentedParametersOfDisabledEffects) {
  const Scene scene = LoadSceneText(std::string(kMinimal) + R"(
[effects]
contact = { enabled = false }
casimir = { enabled = false }
stiction = { enabled = false, adhesion_energy = 0.02 }
van_der_waals = { enabled = false, hamaker = 1e-19 }
damping = { enabled = false, rayleigh = [10.0, 1e-9] }
squeeze_film = { enabled = false, viscosity = 1.9e-5, mean_free_path = 6.8e-8 }
[effects.electrostatic]
enabled = false
voltage = 12.5
fringing = true
electrode_start = 1e-5
electrode_end = 5e-5
)",
                                    "effects.toml");
  const SceneEffects& e = scene.effects;
  ASSERT_TRUE(e.contact && e.casimir && e.stiction && e.electrostatic && e.van_der_waals &&
              e.damping && e.squeeze_film);
  EXPECT_FALSE(e.contact->enabled || e.casimir->enabled || e.stiction->enabled ||
               e.electrostatic->enabled || e.van_der_waals->enabled || e.damping->enabled ||
               e.squeeze_film->enabled);
  EXPECT_EQ(e.squeeze_film->viscosity, 1.9e-5);
  EXPECT_EQ(e.squeeze_film->mean_free_path, 6.8e-8);
  EXPECT_EQ(e.stiction->adhesion_energy, 0.02);
  EXPECT_EQ(e.electrostatic->voltage, 12.5);
  EXPECT_TRUE(e.electrostatic->fringing);
  EXPECT_EQ(e.electrostatic->electrode_start, 1e-5);
  EXPECT_EQ(e.electrostatic->electrode_end, 5e-5);
  EXPECT_EQ(e.van_der_waals->hamaker, 1e-19);
  EXPECT_FALSE(e.damping->quality_factor.has_value());
  ASSERT_TRUE(e.damping->rayleigh.has_value());
  EXPECT_EQ((*e.damping->rayleigh)[0], 10.0);
  EXPECT_EQ((*e.damping->rayleigh)[1], 1e-9);
}

TEST(SceneLoaderTest, EffectParametersWithoutDefaultsStayEmpty) {
  const Scene scene = LoadSceneText(std::string(kMinimal) + R"(
[effects.electrostatic]
enabled = false
[effects.damping]
enabled = false
quality_factor = 100
)",
                                    "effects.toml");
  EXPECT_FALSE(scene.effects.electrostatic->voltage.has_value());
  EXPECT_FALSE(scene.effects.electrostatic->fringing);
  EXPECT_FALSE(scene.effects.electrostatic->electrode_start.has_value());
  EXPECT_EQ(scene.effects.damping->quality_factor, 100.0);
  EXPECT_FALSE(scene.effects.damping->rayleigh.has_value());
}

}  // namespace
}  // namespace cosmems
