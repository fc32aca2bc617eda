// The trajectory fuzzer's kept inputs (its seeds and every input that once failed) replayed
// through the same entry point on the ordinary build: each is refused with a clear error or
// played through a scripted device within the safety layer's bounds (a breach aborts).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "trajectory_fuzz_input.hpp"

namespace cosmems {
namespace {

TEST(TrajectoryFuzzInputsTest, EveryKeptInputPlaysWithinTheBoundsOrIsRefused) {
  for (const char* name : {"trajectory_seeds", "trajectory_regressions"}) {
    const std::filesystem::path dir = std::filesystem::path(COSMEMS_FUZZ_DIR) / name;
    ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
    int inputs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      ASSERT_FALSE(bytes.empty()) << entry.path();
      EXPECT_NO_THROW(fuzz::PlayFuzzedTrajectory(
          reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()))
          << entry.path();
      ++inputs;
    }
    EXPECT_GT(inputs, 0) << dir << " holds no input: the replay would test nothing";
  }
}

}  // namespace
}  // namespace cosmems
