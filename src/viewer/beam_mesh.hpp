#pragma once

#include "cosmems/haptics/haptic_frame.hpp"
#include "display_space.hpp"
#include "mesh.hpp"

namespace cosmems::viewer {

/// The beam as the display draws it: a box of the beam's width and thickness swept along the
/// deflected centreline of `frame`, its cross-sections turned with the frames (the slope
/// theta_z), so the faces tilt as the beam bends. Between two nodes the centreline is the
/// element's own Hermite cubic in u_y and theta_z, sampled `samples_per_element` times.
/// Fills `mesh` (cleared first) in `space`; reuses its storage frame after frame.
void BuildBeamMesh(const HapticFrame& frame, double width_m, double thickness_m,
                   const DisplaySpace& space, Mesh& mesh, int samples_per_element = 4);

}  // namespace cosmems::viewer
