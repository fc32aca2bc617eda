#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "cosmems/scene/scene.hpp"

namespace cosmems {

/// One `--set KEY=VALUE`: a dotted key and a value in TOML syntax.
///
/// Applied to the scene's TOML before validation, it replaces the key or creates it, together
/// with any missing table on its path (`effects.casimir.enabled=true` adds [effects.casimir]).
/// VALUE is read as the right-hand side of a TOML assignment (`8`, `150e-6`, `"modal"`,
/// `[0, -1e-6, 0]`, `{ voltage = 5.0 }`). Extension to TOML: a VALUE that does not parse but is a
/// bare word, [A-Za-z_][A-Za-z0-9_.-]*, is taken as a string, so `analysis.type=modal` works
/// without shell-quoted quotes.
struct SceneOverride {
  std::string key;
  std::string value;

  /// Splits "KEY=VALUE" at the first '=' and trims blanks around both. Throws SceneError
  /// (source "--set") when there is no '=' or KEY is empty.
  static SceneOverride Parse(const std::string& assignment);
};

/// Reads a scene file, applies `overrides` in order and validates the result.
///
/// Throws SceneError, naming `path` (or "--set" for a key an override wrote), the dotted key and
/// the value, for an unreadable file, one that is not a regular file or holds more than 1 MiB,
/// invalid TOML, a missing required key, a value of the wrong type or outside its range (see
/// doc/scenes.md, Limits), an unknown key or table, and for any combination that this version
/// cannot simulate (a stretching cantilever, contact in a modal analysis, ...).
Scene LoadSceneFile(const std::string& path, const std::vector<SceneOverride>& overrides = {});

/// As LoadSceneFile for scene text in memory; `source` names it in errors and in Scene::source.
Scene LoadSceneText(std::string_view toml, const std::string& source,
                    const std::vector<SceneOverride>& overrides = {});

/// An embedded scene by name (see EmbeddedScenes()), otherwise a scene file by path.
Scene LoadScene(const std::string& name_or_path, const std::vector<SceneOverride>& overrides = {});

}  // namespace cosmems
