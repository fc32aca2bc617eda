#pragma once

#include <stdexcept>
#include <string>

namespace cosmems::internal {

/// A file of --out that could not be written (the disk full, the folder read-only): not the
/// user's input at fault but the system, so the command exits 1, not 2. what() is one line: the
/// path and the system's reason.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cosmems::internal
