#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace cosmems::internal {

/// One sample of a sweep as samples.jsonl holds it: its index, its parameters {KEY: value},
/// its status ("ok", the scene's numerical status, "invalid: ..." for a value the scene refuses
/// or "error: ..." for a sample that failed otherwise) and the scene's JSON result (null when it
/// did not run).
struct SweepRow {
  std::int64_t index = 0;
  nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
  std::string status;
  nlohmann::ordered_json result;

  bool ok() const { return status == "ok"; }
  nlohmann::ordered_json Json() const {
    return {{"index", index}, {"parameters", parameters}, {"status", status}, {"result", result}};
  }
  /// The row as one line of samples.jsonl, without its newline. Bytes that are not UTF-8 (a
  /// scene file's name) become U+FFFD rather than an exception that would lose the row.
  std::string Text() const {
    return Json().dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  }
  /// Throws nlohmann::json::exception for an object that is not a row.
  static SweepRow FromJson(const nlohmann::ordered_json& json) {
    SweepRow row;
    row.index = json.at("index").get<std::int64_t>();
    row.parameters = json.at("parameters");
    row.status = json.at("status").get<std::string>();
    row.result = json.at("result");
    return row;
  }
};

}  // namespace cosmems::internal
