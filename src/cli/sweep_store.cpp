#include "sweep_store.hpp"

#include <map>
#include <set>
#include <string>

#include "cli_input_error.hpp"
#include "csv_file.hpp"
#include "sweep_outputs.hpp"

namespace cosmems::internal {
namespace {

constexpr const char* kSweepFile = "sweep.json";
constexpr const char* kSamplesFile = "samples.jsonl";

// A cell of the CSV: a number exact, a string as it is unless it needs quotes.
std::string Cell(const nlohmann::ordered_json& value) {
  if (value.is_number()) return CsvFile::Number(value.get<double>());
  const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

SweepStore::SweepStore(const std::filesystem::path& directory, const nlohmann::ordered_json& sweep)
    : directory_(directory) {
  const std::string where = "--out " + directory.string();
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error || !std::filesystem::is_directory(directory)) {
    throw CliInputError(where + ": cannot create the directory" +
                        (error ? ": " + error.message() : std::string()));
  }
  const std::filesystem::path asked = directory / kSweepFile;
  if (std::filesystem::exists(asked)) {
    std::ifstream in(asked);
    const nlohmann::ordered_json before = nlohmann::ordered_json::parse(in, nullptr, false);
    if (before != sweep) {
      throw CliInputError(where + " holds another sweep (its " + kSweepFile +
                          " differs): choose another folder or delete it");
    }
  } else {
    std::ofstream out(asked);
    out << sweep.dump(2) << "\n";
    if (!out) throw CliInputError(where + ": cannot write " + kSweepFile);
  }
  // The rows so far; a last line without its newline was cut short and is dropped.
  const std::filesystem::path samples = directory / kSamplesFile;
  std::uintmax_t kept = 0;
  if (std::filesystem::exists(samples)) {
    std::ifstream in(samples, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::set<std::int64_t> seen;
    std::size_t start = 0;
    int line = 0;
    for (std::size_t end; (end = text.find('\n', start)) != std::string::npos; start = end + 1) {
      ++line;
      try {
        SweepRow row =
            SweepRow::FromJson(nlohmann::ordered_json::parse(text.substr(start, end - start)));
        if (seen.insert(row.index).second) previous_.push_back(std::move(row));
      } catch (const nlohmann::json::exception& e) {
        throw CliInputError(where + ": " + kSamplesFile + " line " + std::to_string(line) +
                            " is not a sample row (" + e.what() + ")");
      }
    }
    kept = start;
  }
  if (kept > 0 || std::filesystem::exists(samples)) std::filesystem::resize_file(samples, kept);
  samples_.open(samples, std::ios::app);
  if (!samples_) throw CliInputError(where + ": cannot write " + kSamplesFile);
}

void SweepStore::Append(const SweepRow& row) {
  samples_ << row.Json().dump() << "\n";
  samples_.flush();
  if (!samples_) {
    throw CliInputError("--out " + directory_.string() + ": cannot write " + kSamplesFile);
  }
}

void WriteSweepCsv(const std::filesystem::path& path, const std::vector<SweepRow>& rows) {
  std::vector<std::string> keys, fields;
  std::set<std::string> known;
  for (const SweepRow& row : rows) {
    for (const auto& [key, value] : row.parameters.items()) {
      if (known.insert("parameter " + key).second) keys.push_back(key);
    }
    for (const auto& [field, value] : NumericOutputs(row.result)) {
      if (known.insert("output " + field).second) fields.push_back(field);
    }
  }
  std::string header = "index";
  for (const std::string& key : keys) header += "," + key;
  header += ",status";
  for (const std::string& field : fields) header += "," + field;
  CsvFile csv(path, header);
  for (const SweepRow& row : rows) {
    std::vector<std::string> cells = {std::to_string(row.index)};
    for (const std::string& key : keys) {
      cells.push_back(row.parameters.contains(key) ? Cell(row.parameters[key]) : "");
    }
    cells.push_back(Cell(row.status));
    std::map<std::string, double> outputs;
    for (const auto& [field, value] : NumericOutputs(row.result)) outputs[field] = value;
    for (const std::string& field : fields) {
      const auto found = outputs.find(field);
      cells.push_back(found == outputs.end() ? "" : CsvFile::Number(found->second));
    }
    csv.Row(cells);
  }
  csv.Close();
}

}  // namespace cosmems::internal
