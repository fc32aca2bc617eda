#include "analysis_report.hpp"

namespace cosmems::internal {

nlohmann::ordered_json AnalysisReport::Json() const {
  nlohmann::ordered_json json;
  header_.AddJson(json);
  if (header_.status == Status::kOk) AddResults(json);
  json["warnings"] = header_.warnings;
  return json;
}

void AnalysisReport::PrintSummary(std::ostream& out) const {
  header_.Print(out);
  if (header_.status == Status::kOk) {
    out << "\n";
    PrintResults(out);
  }
  for (const std::string& warning : header_.warnings) out << "warning: " << warning << "\n";
}

}  // namespace cosmems::internal
