#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "atomic_file.hpp"

namespace cosmems::internal {

/// A CSV file with a header row, written row by row. It appears whole at Close() or not at all
/// (AtomicFile: a symbolic link in its place is replaced, not followed). Throws OutputFileError
/// naming the file and the system's reason when it cannot be written.
class CsvFile {
 public:
  CsvFile(const std::filesystem::path& path, const std::string& header);

  /// One row; cells are written as given, joined by commas.
  void Row(const std::vector<std::string>& cells);
  /// One row per row of `values`, each number exact (Number()), after `first_cell` if given.
  void Rows(const Eigen::MatrixXd& values, const std::string& first_cell = "");
  /// Writes the file to the disk under its name.
  void Close();

  /// A number in the shortest form that reads back exactly (0.0002, 1.5e-07).
  static std::string Number(double value);
  /// A number rounded to `significant_digits`, trailing zeros dropped (3e-06, 0.000125).
  static std::string Number(double value, int significant_digits);

 private:
  AtomicFile file_;
  std::string line_;  ///< the row being joined, kept to reuse its memory
};

}  // namespace cosmems::internal
