#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace cosmems::internal {

/// A CSV file with a header row, written row by row. Throws CliInputError naming the file when
/// it cannot be opened or written.
class CsvFile {
 public:
  CsvFile(const std::filesystem::path& path, const std::string& header);

  /// One row; cells are written as given, joined by commas.
  void Row(const std::vector<std::string>& cells);
  /// One row per row of `values`, each number exact (Number()), after `first_cell` if given.
  void Rows(const Eigen::MatrixXd& values, const std::string& first_cell = "");
  /// Flushes and checks that everything reached the file.
  void Close();

  /// A number in the shortest form that reads back exactly (0.0002, 1.5e-07).
  static std::string Number(double value);
  /// A number rounded to `significant_digits`, trailing zeros dropped (3e-06, 0.000125).
  static std::string Number(double value, int significant_digits);

 private:
  void Check();

  std::filesystem::path path_;
  std::ofstream file_;
};

}  // namespace cosmems::internal
