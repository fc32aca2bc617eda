#pragma once

#include "viewer_figures.hpp"
#include "viewer_options.hpp"

namespace cosmems::viewer {

/// Opens the window and runs the viewer until it is closed, or headless for options.frames
/// frames; returns what it measured. Throws SceneError (or std::invalid_argument) for a scene or
/// setting it cannot run, std::runtime_error when there is no display or OpenGL 3.3 context,
/// or when the device or the screenshot fails.
ViewerFigures RunViewer(const ViewerOptions& options);

}  // namespace cosmems::viewer
