#include "csv_file.hpp"

#include "cli_input_error.hpp"
#include "cosmems/core/validation.hpp"

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

void CsvFile::Close() {
  file_.close();
  Check();
}

std::string CsvFile::Number(double value) { return FormatValue(value); }

void CsvFile::Check() {
  if (!file_) {
    throw CliInputError("--out: " + path_.string() + ": cannot write the file");
  }
}

}  // namespace cosmems::internal
