#pragma once

#include <stdexcept>
#include <string>

namespace cosmems::internal {

/// Invalid command-line input outside the scene itself, such as an --out directory that
/// cannot be written. what() is one line naming the option and the value.
class CliInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace cosmems::internal
