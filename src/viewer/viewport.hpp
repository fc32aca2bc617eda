#pragma once

namespace cosmems::viewer {

/// A rectangle of the window in pixels, from its top-left corner, y down.
struct Viewport {
  int x = 0;
  int y = 0;
  int width = 1;
  int height = 1;

  double Aspect() const { return static_cast<double>(width) / height; }
};

/// Width of the panel on the left [pixels].
inline constexpr int kPanelWidth = 380;

/// The 3-D view: the window right of the panel (the whole window when it is too narrow).
inline Viewport SceneViewport(int window_width, int window_height) {
  const int panel = window_width > 2 * kPanelWidth ? kPanelWidth : 0;
  return Viewport{panel, 0, window_width - panel, window_height > 0 ? window_height : 1};
}

}  // namespace cosmems::viewer
