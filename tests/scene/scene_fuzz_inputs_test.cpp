// The fuzzer's kept inputs — its seeds and every input that once failed — replayed through the
// same entry point on the ordinary build, so a fixed crash stays fixed without clang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "scene_fuzz_input.hpp"

namespace cosmems {
namespace {

// The files of one corpus folder; each folder must exist and hold inputs, or the replay would
// test nothing.
std::vector<std::filesystem::path> KeptInputs(const char* name) {
  const std::filesystem::path dir = std::filesystem::path(COSMEMS_FUZZ_DIR) / name;
  EXPECT_TRUE(std::filesystem::is_directory(dir)) << dir;
  std::vector<std::filesystem::path> files;
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  EXPECT_FALSE(files.empty()) << dir;
  return files;
}

TEST(SceneFuzzInputsTest, EveryKeptInputLoadsOrFailsWithASceneError) {
  std::vector<std::filesystem::path> files = KeptInputs("seeds");
  for (const auto& regression : KeptInputs("regressions")) files.push_back(regression);
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_FALSE(bytes.empty()) << file;
    EXPECT_NO_THROW(
        fuzz::LoadFuzzedScene(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()))
        << file;
  }
}

}  // namespace
}  // namespace cosmems
