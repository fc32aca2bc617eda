#include "cosmems/scripted/csv_trajectory.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <istream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace cosmems {
namespace {

constexpr const char* kColumns[] = {"time_s", "x_m", "y_m", "z_m"};
constexpr int kColumnCount = 4;
// A recorded run of the longest haptic session (3600 s at 2 kHz, ~130 bytes a row) fits well
// within these; a file past them is refused rather than read into memory.
constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{1} << 30;
constexpr std::size_t kMaxRows = 10'000'000;

/// Samples interpolated linearly, held outside their time span.
class CsvTrajectory final : public Trajectory {
 public:
  CsvTrajectory(std::vector<double> times, std::vector<Eigen::Vector3d> positions)
      : times_(std::move(times)), positions_(std::move(positions)) {}

  Eigen::Vector3d Position(double t_s) const override {
    if (!(t_s > times_.front())) return positions_.front();
    if (t_s >= times_.back()) return positions_.back();
    // First sample after t_s: it exists and is not the first, by the two tests above.
    const auto after = std::upper_bound(times_.begin(), times_.end(), t_s);
    const auto i = static_cast<std::size_t>(after - times_.begin());
    const double w = (t_s - times_[i - 1]) / (times_[i] - times_[i - 1]);
    return (1.0 - w) * positions_[i - 1] + w * positions_[i];
  }
  double Duration() const override { return times_.back(); }

 private:
  std::vector<double> times_;
  std::vector<Eigen::Vector3d> positions_;
};

std::string_view Trim(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> SplitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (;;) {
    const auto comma = line.find(',');
    fields.push_back(Trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

/// Builds the error messages: "<file>:<line>: <what>".
class CsvErrors {
 public:
  explicit CsvErrors(const std::string& path) : path_(path) {}

  [[noreturn]] void Throw(long line, const std::string& what) const {
    std::ostringstream message;
    message << path_;
    if (line > 0) message << ':' << line;
    message << ": " << what;
    throw std::invalid_argument(message.str());
  }

 private:
  const std::string& path_;
};

void CheckHeader(const std::vector<std::string_view>& header, const CsvErrors& errors) {
  const std::string expected = "time_s,x_m,y_m,z_m";
  if (static_cast<int>(header.size()) < kColumnCount) {
    errors.Throw(1, "header row has " + std::to_string(header.size()) +
                        " fields, expected at least " + std::to_string(kColumnCount) + ": " +
                        expected);
  }
  for (int c = 0; c < kColumnCount; ++c) {
    if (header[static_cast<std::size_t>(c)] != kColumns[c]) {
      errors.Throw(1, "header column " + std::to_string(c + 1) + " is '" +
                          std::string(header[static_cast<std::size_t>(c)]) + "', expected '" +
                          kColumns[c] + "' (the header must begin " + expected + ")");
    }
  }
}

double ParseField(std::string_view text, int column, long line, const CsvErrors& errors) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  const std::string field = std::string(kColumns[column]) + " = '" + std::string(text) + "'";
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
    errors.Throw(line, field + " is not a number");
  }
  if (!std::isfinite(value)) errors.Throw(line, field + " is not finite");
  return value;
}

}  // namespace

std::unique_ptr<Trajectory> ReadCsvTrajectory(std::istream& in, const std::string& name) {
  const CsvErrors errors(name);
  std::string text;
  long line = 0;
  std::size_t columns = 0;
  std::vector<double> times;
  std::vector<Eigen::Vector3d> positions;
  while (std::getline(in, text)) {
    ++line;
    if (line > 1 && Trim(text).empty()) continue;
    const std::vector<std::string_view> fields = SplitFields(text);
    if (line == 1) {
      CheckHeader(fields, errors);
      columns = fields.size();
      continue;
    }
    if (fields.size() != columns) {
      errors.Throw(line, std::to_string(fields.size()) + " fields, expected " +
                             std::to_string(columns) + " as in the header");
    }
    if (times.size() == kMaxRows) {
      errors.Throw(line, "more than " + std::to_string(kMaxRows) + " rows");
    }
    double row[kColumnCount];
    for (int c = 0; c < kColumnCount; ++c) {
      row[c] = ParseField(fields[static_cast<std::size_t>(c)], c, line, errors);
    }
    if (!times.empty() && !(row[0] > times.back())) {
      std::ostringstream what;
      what << "time_s = '" << fields[0] << "' is not after the previous row's time " << times.back()
           << " (times must increase strictly)";
      errors.Throw(line, what.str());
    }
    times.push_back(row[0]);
    positions.emplace_back(row[1], row[2], row[3]);
  }
  if (in.bad()) errors.Throw(line, "read error");
  if (line == 0) errors.Throw(1, "the header row time_s,x_m,y_m,z_m is missing (empty file)");
  if (times.empty()) errors.Throw(0, "no data rows after the header");
  return std::make_unique<CsvTrajectory>(std::move(times), std::move(positions));
}

std::unique_ptr<Trajectory> LoadCsvTrajectory(const std::string& path) {
  const CsvErrors errors(path);
  // A FIFO or a device (/dev/zero) would be read for ever: only a regular file of bounded size.
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    errors.Throw(0, std::filesystem::exists(path, error)
                        ? "not a regular file (a trajectory is a CSV file)"
                        : "cannot open the trajectory file");
  }
  const std::uintmax_t bytes = std::filesystem::file_size(path, error);
  if (error || bytes > kMaxFileBytes) {
    errors.Throw(0,
                 "the trajectory file is larger than " + std::to_string(kMaxFileBytes) + " bytes");
  }
  std::ifstream file(path);
  if (!file) errors.Throw(0, "cannot open the trajectory file");
  return ReadCsvTrajectory(file, path);
}

}  // namespace cosmems
