#pragma once

#include <string_view>
#include <vector>

namespace cosmems {

/// A scene compiled into the library: the text of one of the scene files shipped with cosmems,
/// comments included, so that printing it gives a file to copy and edit.
struct EmbeddedScene {
  std::string_view name;         ///< what `cosmems run NAME` and `cosmems show NAME` take
  std::string_view description;  ///< one line: the file's first comment
  std::string_view toml;         ///< the whole scene file
};

/// Every embedded scene, in name order.
const std::vector<EmbeddedScene>& EmbeddedScenes();

/// The embedded scene called `name`, or nullptr when there is none.
const EmbeddedScene* FindEmbeddedScene(std::string_view name);

}  // namespace cosmems
