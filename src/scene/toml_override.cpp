#include "toml_override.hpp"

#include <string>
#include <string_view>
#include <vector>

#include "cosmems/scene/scene_error.hpp"
#include "key_origins.hpp"
#include "toml_format.hpp"

namespace cosmems::internal {
namespace {

constexpr std::string_view kValueKey = "value";

[[noreturn]] void Fail(const SceneOverride& assignment, const std::string& reason) {
  throw SceneError(KeyOrigins::kOverride, assignment.key, assignment.value, reason);
}

std::vector<std::string> SplitKey(const SceneOverride& assignment) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t dot = assignment.key.find('.', begin);
    parts.push_back(assignment.key.substr(begin, dot - begin));
    if (!IsBareKey(parts.back())) {
      Fail(assignment, "KEY must be dotted bare keys, such as model.elements");
    }
    if (dot == std::string::npos) return parts;
    begin = dot + 1;
  }
}

// [A-Za-z_][A-Za-z0-9_.-]*: a word a shell user would not think of quoting.
bool IsBareWord(std::string_view text) {
  auto letter = [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; };
  if (text.empty() || !letter(text.front())) return false;
  for (const char c : text) {
    if (!letter(c) && !(c >= '0' && c <= '9') && c != '.' && c != '-') return false;
  }
  return true;
}

// The value as a one-entry table { value = VALUE }.
toml::table ParseValue(const SceneOverride& assignment) {
  try {
    const std::string text = std::string(kValueKey) + " = " + assignment.value;
    toml::table parsed = toml::parse(std::string_view(text), std::string_view("--set"));
    // More than one entry means VALUE smuggled in a line break and further keys.
    if (parsed.size() == 1) return parsed;
  } catch (const toml::parse_error&) {
    // Not TOML: perhaps a bare word, below.
  }
  if (!IsBareWord(assignment.value)) {
    Fail(assignment, "not a TOML value (strings take quotes: 'KEY=\"text\"')");
  }
  toml::table word;
  word.insert(kValueKey, assignment.value);
  return word;
}

}  // namespace

void ApplyOverride(toml::table& root, const SceneOverride& assignment) {
  const std::vector<std::string> path = SplitKey(assignment);
  toml::table parsed = ParseValue(assignment);
  toml::table* table = &root;
  std::string walked;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    walked += (i == 0 ? "" : ".") + path[i];
    toml::node* next = table->get(path[i]);
    if (next == nullptr) next = &table->insert(path[i], toml::table{}).first->second;
    if (!next->is_table()) {
      Fail(assignment, walked + " = " + FormatToml(*next) + " is not a table");
    }
    table = next->as_table();
  }
  parsed.get(kValueKey)->visit(
      [&](auto& value) { table->insert_or_assign(path.back(), std::move(value)); });
}

}  // namespace cosmems::internal
