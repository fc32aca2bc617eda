#include "sweep_request.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli_errors.hpp"
#include "cosmems/scene/embedded_scenes.hpp"
#include "cosmems/scene/scene_error.hpp"
#include "cosmems/scene/scene_loader.hpp"

namespace cosmems::internal {
namespace {

// LoadSceneFile's limit on a scene file (doc/scenes.md, Limits).
constexpr std::uintmax_t kMaxSceneBytes = 1 << 20;

}  // namespace

std::pair<std::string, std::string> SweepRequest::SplitVary(const std::string& assignment) {
  // --set's split, with the option's own message.
  try {
    SceneOverride split = SceneOverride::Parse(assignment);
    return {std::move(split.key), std::move(split.value)};
  } catch (const SceneError&) {
    throw CliInputError("--vary " + assignment + ": expected KEY=SPEC");
  }
}

void SweepRequest::SetShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  std::size_t used_k = 0, used_n = 0;
  try {
    if (slash != std::string::npos) {
      shard = std::stoi(text.substr(0, slash), &used_k);
      shards = std::stoi(text.substr(slash + 1), &used_n);
    }
  } catch (const std::exception&) {
    used_k = 0;
  }
  if (slash == std::string::npos || used_k != slash || used_n != text.size() - slash - 1 ||
      shard < 1 || shard > shards) {
    throw CliInputError("--shard " + text + ": expected K/N with 1 <= K <= N (--shard 2/8)");
  }
}

std::string SceneText(const std::string& scene) {
  if (const EmbeddedScene* embedded = FindEmbeddedScene(scene)) return std::string(embedded->toml);
  std::error_code error;
  // What LoadScene refuses (a FIFO, /dev/zero, a file above its limit) is never read here.
  if (std::filesystem::is_regular_file(scene, error) &&
      std::filesystem::file_size(scene, error) <= kMaxSceneBytes) {
    std::ifstream in(scene, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (in) return text.str();
  }
  (void)LoadScene(scene);  // throws the SceneError that names why
  throw SceneError(scene, "", "", "cannot read the scene file");
}

void SweepRequest::MergeSceneTable(const std::string& toml, const std::string& source) {
  toml::table parsed;
  try {
    parsed = toml::parse(toml, source);
  } catch (const toml::parse_error&) {
    return;
  }
  const toml::node* node = parsed.get("sweep");
  if (node == nullptr) return;
  auto fail = [&](const std::string& key, const std::string& why) -> void {
    throw SceneError(source, "sweep" + (key.empty() ? "" : "." + key), "", why);
  };
  const toml::table* table = node->as_table();
  if (table == nullptr) fail("", "expected a table");
  for (const auto& [name, value] : *table) {
    const std::string key(name.str());
    if (key == "method") {
      if (!value.is_string()) fail(key, "expected a string");
      if (!method) method = *value.value<std::string>();
    } else if (key == "samples") {
      if (!value.is_integer()) fail(key, "expected an integer");
      if (!samples) samples = *value.value<std::int64_t>();
    } else if (key == "seed") {
      if (!value.is_integer() || *value.value<std::int64_t>() < 0) {
        fail(key, "expected a non-negative integer");
      }
      if (!seed) seed = static_cast<std::uint64_t>(*value.value<std::int64_t>());
    } else if (key == "specs") {
      const toml::array* list = value.as_array();
      if (list == nullptr) fail(key, "expected a list of strings");
      std::vector<std::string> table_specs;
      for (const toml::node& spec : *list) {
        if (!spec.is_string()) fail(key, "expected a list of strings");
        table_specs.push_back(*spec.value<std::string>());
      }
      specs.insert(specs.begin(), table_specs.begin(), table_specs.end());
    } else if (key == "vary") {
      const toml::table* keys = value.as_table();
      if (keys == nullptr) fail(key, "expected a table of KEY = \"SPEC\"");
      std::vector<std::pair<std::string, std::string>> table_vary;
      for (const auto& [varied, spec] : *keys) {
        if (!spec.is_string()) fail("vary." + std::string(varied.str()), "expected a SPEC string");
        const std::string k(varied.str());
        const bool overridden = std::any_of(vary.begin(), vary.end(),
                                            [&](const auto& given) { return given.first == k; });
        if (!overridden) table_vary.emplace_back(k, *spec.value<std::string>());
      }
      vary.insert(vary.begin(), table_vary.begin(), table_vary.end());
    } else {
      fail(key, "unknown key (expected method, samples, seed, specs, vary)");
    }
  }
}

}  // namespace cosmems::internal
