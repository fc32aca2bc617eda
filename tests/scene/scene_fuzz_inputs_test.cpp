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

std::vector<std::filesystem::path> KeptInputs() {
  std::vector<std::filesystem::path> files;
  for (const char* name : {"seeds", "regressions"}) {
    const std::filesystem::path dir = std::filesystem::path(COSMEMS_FUZZ_DIR) / name;
    if (!std::filesystem::is_directory(dir)) continue;  // no regression yet
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      if (entry.is_regular_file()) files.push_back(entry.path());
    }
  }
  return files;
}

TEST(SceneFuzzInputsTest, EveryKeptInputLoadsOrFailsWithASceneError) {
  const std::vector<std::filesystem::path> files = KeptInputs();
  ASSERT_GE(files.size(), 5u);  // the seeds at least: an empty list would test nothing
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
