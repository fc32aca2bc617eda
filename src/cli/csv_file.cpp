#include "csv_file.hpp"

#include <array>
#include <charconv>

namespace cosmems::internal {

CsvFile::CsvFile(const std::filesystem::path& path, const std::string& header) : file_(path) {
  file_.Write(header);
  file_.Write("\n");
}

void CsvFile::Row(const std::vector<std::string>& cells) {
  line_.clear();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) line_ += ',';
    line_ += cells[i];
  }
  line_ += '\n';
  file_.Write(line_);
}

void CsvFile::Rows(const Eigen::MatrixXd& values, const std::string& first_cell) {
  for (Eigen::Index r = 0; r < values.rows(); ++r) {
    std::vector<std::string> cells;
    if (!first_cell.empty()) cells.push_back(first_cell);
    for (Eigen::Index c = 0; c < values.cols(); ++c) cells.push_back(Number(values(r, c)));
    Row(cells);
  }
}

void CsvFile::Close() { file_.Commit(); }

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

}  // namespace cosmems::internal
