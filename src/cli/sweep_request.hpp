#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cosmems::internal {

/// What `cosmems sweep` was asked (doc/sweeps.md). The scene's own [sweep] table fills what
/// the command line leaves out: a --vary replaces the table's spec of its key, --spec adds to
/// its specs, --method, --samples and --seed replace its values.
struct SweepRequest {
  std::string scene;
  std::vector<std::string> sets;  ///< --set KEY=VALUE, applied to every sample
  std::vector<std::pair<std::string, std::string>> vary;  ///< KEY, SPEC in order
  std::vector<std::string> specs;
  std::vector<std::string> plots;  ///< --plot FIELD (none: DefaultPlotFields)
  std::optional<std::string> method;
  std::optional<std::int64_t> samples;
  std::optional<std::uint64_t> seed;
  int threads = 0;  ///< 0: one per hardware thread
  int shard = 1;    ///< this shard, 1..shards
  int shards = 1;
  std::string out;
  bool json = false;

  /// Splits "KEY=SPEC" at the first '=' and trims blanks, as --set does; throws CliInputError
  /// naming the option without one.
  static std::pair<std::string, std::string> SplitVary(const std::string& assignment);
  /// Reads "K/N" with 1 <= K <= N into shard and shards; throws CliInputError otherwise.
  void SetShard(const std::string& text);
  /// Adds the [sweep] table of the scene text `toml` (read from `source`) beneath the command
  /// line's choices. Throws SceneError naming the key for a table that is not as described; text
  /// that is not TOML is left to the scene's loading, which names the error's place.
  void MergeSceneTable(const std::string& toml, const std::string& source);
};

/// The text of an embedded scene or of a scene file. Throws SceneError, as LoadScene does, for a
/// name that is neither, or a file that is unreadable, not a regular file or too large.
std::string SceneText(const std::string& scene);

}  // namespace cosmems::internal
