#pragma once

#include "cosmems/surface/contact_state.hpp"
#include "viewport.hpp"

namespace cosmems::viewer {

/// The proximity warning: a popup at the top of the 3-D view while the structure (`what`: "beam"
/// or "device") is near the substrate, touching it or stuck to it (the paper's warning before
/// failure), saying which.
void DrawSurfaceWarning(const ContactSummary& contact, const char* what, const Viewport& viewport);

/// The view's caption at its bottom: how the mouse works and the vertical scale, so that no one
/// reads the stretched deflection as the real one.
void DrawViewCaption(const Viewport& viewport, double exaggeration, bool mouse_drives_stylus);

}  // namespace cosmems::viewer
