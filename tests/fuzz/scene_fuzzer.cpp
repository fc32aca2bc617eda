// libFuzzer entry point for the scene reader and `--set` (built with clang, COSMEMS_BUILD_FUZZERS).
#include <cstddef>
#include <cstdint>

#include "scene_fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  cosmems::fuzz::LoadFuzzedScene(data, size);
  return 0;
}
