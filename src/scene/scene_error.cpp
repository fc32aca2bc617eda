#include "cosmems/scene/scene_error.hpp"

namespace cosmems {
namespace {

// The message must stay one line whatever a file name or a --set value holds.
std::string OneLine(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') {
      out += "\\n";
    } else if (c == '\r') {
      out += "\\r";
    } else {
      out += c;
    }
  }
  return out;
}

std::string Message(const std::string& source, const std::string& key, const std::string& value,
                    const std::string& reason) {
  std::string message = source + ": ";
  if (!key.empty()) message += value.empty() ? key + ": " : key + " = " + value + ": ";
  return OneLine(message + reason);
}

}  // namespace

SceneError::SceneError(const std::string& source, const std::string& key, const std::string& value,
                       const std::string& reason)
    : std::invalid_argument(Message(source, key, value, reason)),
      source_(source),
      key_(key),
      value_(value) {}

}  // namespace cosmems
