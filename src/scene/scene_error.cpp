#include "cosmems/scene/scene_error.hpp"

#include "cosmems/scene/printable_text.hpp"

namespace cosmems {
namespace {

std::string Message(const std::string& source, const std::string& key, const std::string& value,
                    const std::string& reason) {
  std::string message = source + ": ";
  if (!key.empty()) message += value.empty() ? key + ": " : key + " = " + value + ": ";
  // One line, and nothing a terminal would act on, whatever a file name or a --set value holds.
  return PrintableText(message + reason);
}

}  // namespace

SceneError::SceneError(const std::string& source, const std::string& key, const std::string& value,
                       const std::string& reason)
    : std::invalid_argument(Message(source, key, value, reason)),
      source_(source),
      key_(key),
      value_(value) {}

}  // namespace cosmems
