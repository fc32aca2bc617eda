// libFuzzer entry point for the CSV trajectory reader and the scripted device that plays it
// (built with clang, COSMEMS_BUILD_FUZZERS).
#include <cstddef>
#include <cstdint>

#include "trajectory_fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cosmems::fuzz::PlayFuzzedTrajectory(data, size);
  return 0;
}
