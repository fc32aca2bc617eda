#include "csv_file.hpp"

#include <array>
#include <charconv>

#include "cli_input_error.hpp"

namespace cosmems::internal {

CsvFile::CsvFile(const std::filesystem::path& path, const std::string& header)
    : path_(path), file_(path) {
  Check();
  file_ << header << '\n';
}

void CsvFile::Row(const std::vector<std::string>& cells) {
  for (std::size_t i = 0; i < cells.size(); ++i) file_ << (i == 0 ? "" : ",") << cells[i];
  file_ << '\n';
}

void CsvFile::Rows(const Eigen::MatrixXd& values, const std::string& first_cell) {
  for (Eigen::Index r = 0; r < values.rows(); ++r) {
    std::vector<std::string> cells;
    if (!first_cell.empty()) cells.push_back(first_cell);
    for (Eigen::Index c = 0; c < values.cols(); ++c) cells.push_back(Number(values(r, c)));
    Row(cells);
  }
}

void CsvFile::Close() {
  file_.close();
  Check();
}

std::string CsvFile::Number(double value) {
  std::array<char, 32> buffer{};
  // + 0.0 turns -0 (a supported rotation, say) into 0: a table of results has no use for it.
  const std::to_chars_result end =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value + 0.0);
  return {buffer.data(), end.ptr};
}

std::string CsvFile::Number(double value, int significant_digits) {
  std::array<char, 48> buffer{};
  const std::to_chars_result end =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value + 0.0,
                    std::chars_format::general, significant_digits);
  return {buffer.data(), end.ptr};
}

void CsvFile::Check() {
  if (!file_) {
    throw CliInputError("--out: " + path_.string() + ": cannot write the file");
  }
}

}  // namespace cosmems::internal
