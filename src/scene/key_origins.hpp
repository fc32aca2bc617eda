#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace cosmems::internal {

/// Where each key of a scene came from: the scene file (or embedded scene), or a `--set`. Error
/// messages name the origin, so a bad value typed on the command line is not blamed on the file.
class KeyOrigins {
 public:
  static constexpr const char* kOverride = "--set";

  explicit KeyOrigins(std::string source) : source_(std::move(source)) {}

  /// Records that a --set wrote `key` (and everything below it).
  void AddOverride(std::string key) { overrides_.push_back(std::move(key)); }

  /// "--set" when an override wrote `key`, a table holding it or a key inside it; otherwise
  /// the scene's source.
  std::string SourceOf(std::string_view key) const;

  const std::string& source() const { return source_; }

 private:
  std::string source_;
  std::vector<std::string> overrides_;
};

}  // namespace cosmems::internal
