#pragma once

#include <toml++/toml.h>

#include "cosmems/scene/scene.hpp"
#include "key_origins.hpp"

namespace cosmems::internal {

/// The schema of doc/scenes.md: reads a parsed scene into a Scene, checking types, ranges, unknown
/// keys, the loads against the structure and model, and refusing what this version cannot
/// simulate. Throws SceneError; Scene::source is left to the caller.
Scene ReadScene(const toml::table& root, const KeyOrigins& origins);

}  // namespace cosmems::internal
