#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <ostream>

#include "run_header.hpp"

namespace cosmems::internal {

/// The outcome of one analysis in each form the CLI reports it: one JSON object, a readable
/// summary, and files for --out. Results beyond the header are reported only when the status is
/// ok: a failed solve has none worth printing.
class AnalysisReport {
 public:
  explicit AnalysisReport(RunHeader header) : header_(std::move(header)) {}
  virtual ~AnalysisReport() = default;
  AnalysisReport(const AnalysisReport&) = delete;
  AnalysisReport& operator=(const AnalysisReport&) = delete;

  const RunHeader& header() const { return header_; }

  /// The header's fields, then the analysis's, then `warnings` (an array, maybe empty).
  nlohmann::ordered_json Json() const;

  /// The header lines, the results in SI with a few significant digits, then any warnings.
  void PrintSummary(std::ostream& out) const;

  /// Writes the analysis's CSV files into `directory`, which exists. Throws CliInputError when
  /// a file cannot be written.
  virtual void WriteFiles(const std::filesystem::path& directory) const = 0;

 protected:
  virtual void AddResults(nlohmann::ordered_json& json) const = 0;
  virtual void PrintResults(std::ostream& out) const = 0;

 private:
  RunHeader header_;
};

}  // namespace cosmems::internal
