#pragma once

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "sweep_row.hpp"

namespace cosmems::internal {

/// A sweep's output folder: `sweep.json` (what was asked: the scene, its --set, the varied
/// keys, method, samples, seed), `samples.jsonl` (one row a line, appended as samples finish).
/// Opening a folder that holds the same sweep resumes it: its rows are read back, a last line
/// cut short by an interruption is dropped, and a row already there is never written twice.
class SweepStore {
 public:
  /// Throws CliInputError naming the folder when it cannot be created or written, holds another
  /// sweep, or a line other than the last is not a row.
  SweepStore(const std::filesystem::path& directory, const nlohmann::ordered_json& sweep);

  const std::filesystem::path& directory() const { return directory_; }
  /// The rows found when the folder was opened, each index once.
  const std::vector<SweepRow>& previous() const { return previous_; }
  /// Appends one row and flushes it (an interrupted sweep keeps every finished sample).
  void Append(const SweepRow& row);

 private:
  std::filesystem::path directory_;
  std::vector<SweepRow> previous_;
  std::ofstream samples_;
};

/// Writes `samples.csv`: index, each parameter, status, then every output that any row has
/// (NumericOutputs), rows in the order given; empty cells where a row lacks an output.
void WriteSweepCsv(const std::filesystem::path& path, const std::vector<SweepRow>& rows);

}  // namespace cosmems::internal
