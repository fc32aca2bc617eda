#pragma once

#include <cstddef>
#include <cstdint>

namespace cosmems::fuzz {

/// Feeds one input to the scene reader the way `cosmems run SCENE --set ...` does: the bytes up
/// to the first NUL are the scene's TOML, and each NUL-separated piece after it is one `--set`
/// assignment. A valid scene is carried on to the core's descriptions and built into its model.
/// SceneError is the only exception bad input may raise; anything else escapes and stops the
/// caller, and a model with non-finite matrices aborts.
void LoadFuzzedScene(const std::uint8_t* data, std::size_t size);

}  // namespace cosmems::fuzz
