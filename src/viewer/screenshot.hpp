#pragma once

#include <string>

namespace cosmems::viewer {

/// Writes the frame just drawn (the back buffer, `width` x `height`, before it is swapped) to
/// `path` as an RGB PNG, top row first. Throws std::runtime_error naming the file when it cannot
/// be written.
void WriteScreenshot(const std::string& path, int width, int height);

}  // namespace cosmems::viewer
