#pragma once

#include <stdexcept>

namespace cosmems::internal {

// The two ways a command fails besides a scene's own errors, told apart by the exit status.

/// Invalid command-line input outside the scene itself, such as an --out directory that
/// cannot be written: the user's input at fault, exit 2. what() is one line naming the option
/// and the value.
class CliInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// A file of --out that could not be written (the disk full, the folder read-only): not the
/// user's input at fault but the system, so the command exits 1. what() is one line: the path
/// and the system's reason.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace cosmems::internal
