#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>
#include <vector>

#include "sweep_row.hpp"

namespace cosmems::internal {

/// A sweep's output folder: `sweep.json` (what was asked: the scene and a hash of its text, its
/// --set, the varied keys, method, samples, seed, the program's version), `samples.jsonl` (one
/// row a line, appended as samples finish). Opening a folder that holds the same sweep resumes
/// it: its rows are read back and a row already there is never written twice.
///
/// Any number of processes (shards) may write into one folder at once: each row is appended by
/// one write under an exclusive lock (flock) of samples.jsonl, and the folder is read under it.
/// A last line cut short (a process killed while writing it) is dropped; any other line that is
/// not a row is skipped with a warning, so its sample runs again.
class SweepStore {
 public:
  /// Throws CliInputError naming the folder when it cannot be created, or holds another sweep
  /// (naming what differs; the folder is then left as it was); OutputFileError naming the file
  /// and the system's reason when a file cannot be read, written or locked, or samples.jsonl is
  /// a symbolic link (never followed). Warnings go to `warnings`, one line each.
  SweepStore(const std::filesystem::path& directory, const nlohmann::ordered_json& sweep,
             std::ostream& warnings);
  ~SweepStore();
  SweepStore(const SweepStore&) = delete;
  SweepStore& operator=(const SweepStore&) = delete;

  const std::filesystem::path& directory() const { return directory_; }
  /// The rows found when the folder was opened, each index once.
  const std::vector<SweepRow>& previous() const { return previous_; }
  /// Appends one row (an interrupted sweep keeps every finished sample).
  void Append(const SweepRow& row);

 private:
  std::filesystem::path directory_;
  std::filesystem::path samples_path_;
  std::vector<SweepRow> previous_;
  int samples_ = -1;  ///< samples.jsonl, open for appending
};

/// Writes `samples.csv`: index, each parameter, status, then every output that any row has
/// (NumericOutputs), rows in the order given; empty cells where a row lacks an output.
void WriteSweepCsv(const std::filesystem::path& path, const std::vector<SweepRow>& rows);

}  // namespace cosmems::internal
