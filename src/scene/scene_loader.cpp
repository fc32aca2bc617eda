#include "cosmems/scene/scene_loader.hpp"

#include <toml++/toml.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "cosmems/scene/embedded_scenes.hpp"
#include "cosmems/scene/scene_error.hpp"
#include "key_origins.hpp"
#include "scene_limits.hpp"
#include "scene_reader.hpp"
#include "toml_override.hpp"

namespace cosmems {
namespace {

std::string Trim(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t") - begin + 1);
}

// A regular file of at most kMaxSceneBytes. Anything else (a FIFO, a device such as /dev/zero)
// could be read without end, so it is refused before it is opened; and since a file may grow
// after its size is asked, reading stops one byte past the limit instead of trusting the size.
std::string ReadFile(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status)) {
    throw SceneError(path, "", "", "is a directory, not a scene file");
  }
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    throw SceneError(path, "", "",
                     "not a regular file (a FIFO, socket or device), not a scene file");
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw SceneError(path, "", "", std::string("cannot open scene file: ") + std::strerror(errno));
  }
  std::string text(internal::kMaxSceneBytes + 1, '\0');
  file.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (file.bad()) throw SceneError(path, "", "", "cannot read scene file");
  text.resize(static_cast<std::size_t>(file.gcount()));
  if (text.size() > internal::kMaxSceneBytes) {
    throw SceneError(path, "", "",
                     "larger than " + std::to_string(internal::kMaxSceneBytes) +
                         " bytes (1 MiB), the most a scene file may hold");
  }
  return text;
}

std::string EmbeddedSceneNames() {
  std::string names;
  for (const EmbeddedScene& scene : EmbeddedScenes()) {
    names += (names.empty() ? "" : ", ") + std::string(scene.name);
  }
  return names;
}

bool LooksLikePath(const std::string& text) {
  const std::string_view suffix = ".toml";
  return text.find('/') != std::string::npos ||
         (text.size() >= suffix.size() &&
          text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0);
}

}  // namespace

SceneOverride SceneOverride::Parse(const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  const std::string key = Trim(assignment.substr(0, equals));
  if (equals == std::string::npos || key.empty()) {
    throw SceneError(internal::KeyOrigins::kOverride, assignment, "",
                     "expected KEY=VALUE, such as model.elements=8");
  }
  return {key, Trim(assignment.substr(equals + 1))};
}

Scene LoadSceneText(std::string_view toml, const std::string& source,
                    const std::vector<SceneOverride>& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml, source);
  } catch (const toml::parse_error& error) {
    const toml::source_position& at = error.source().begin;
    throw SceneError(source, "", "",
                     "invalid TOML at line " + std::to_string(at.line) + ", column " +
                         std::to_string(at.column) + ": " + std::string(error.description()));
  }
  internal::KeyOrigins origins(source);
  for (const SceneOverride& assignment : overrides) {
    internal::ApplyOverride(root, assignment);
    origins.AddOverride(assignment.key);
  }
  Scene scene = internal::ReadScene(root, origins);
  scene.source = source;
  return scene;
}

Scene LoadSceneFile(const std::string& path, const std::vector<SceneOverride>& overrides) {
  return LoadSceneText(ReadFile(path), path, overrides);
}

Scene LoadScene(const std::string& name_or_path, const std::vector<SceneOverride>& overrides) {
  if (const EmbeddedScene* embedded = FindEmbeddedScene(name_or_path)) {
    return LoadSceneText(embedded->toml, name_or_path, overrides);
  }
  std::error_code error;
  if (!LooksLikePath(name_or_path) && !std::filesystem::exists(name_or_path, error)) {
    throw SceneError(name_or_path, "", "",
                     "neither an embedded scene (" + EmbeddedSceneNames() + ") nor a scene file");
  }
  return LoadSceneFile(name_or_path, overrides);
}

}  // namespace cosmems
