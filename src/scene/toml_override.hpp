#pragma once

#include <toml++/toml.h>

#include "cosmems/scene/scene_loader.hpp"

namespace cosmems::internal {

/// Writes one `--set` into a parsed scene (see SceneOverride), creating missing tables on the
/// key's path. Throws SceneError (source "--set") for a key that is not dotted bare words, a
/// value that is neither TOML nor a bare word, or a path through a value that is not a table.
void ApplyOverride(toml::table& root, const SceneOverride& assignment);

}  // namespace cosmems::internal
