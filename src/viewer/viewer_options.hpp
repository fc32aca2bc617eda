#pragma once

#include <string>
#include <vector>

#include "cosmems/scene/scene_loader.hpp"
#include "viewer_session.hpp"

namespace cosmems::viewer {

/// How `cosmems-viewer` runs.
struct ViewerOptions {
  std::string scene = "cantilever-haptic";  ///< an embedded scene or a .toml path
  std::vector<SceneOverride> overrides;     ///< --set, in order
  Input input = Input::kAuto;
  /// Headless: play the scene's scripted stylus, draw `frames` frames and write the last one
  /// here as PNG, then exit. Empty: the interactive window.
  std::string screenshot;
  int frames = 60;
  int width = 1280, height = 800;  ///< the window [pixels]
};

/// Frames drawn per second: the display loop's pace (the servo loop runs at its own 1 kHz).
inline constexpr double kDisplayRateHz = 60.0;

}  // namespace cosmems::viewer
