#pragma once

#include "cosmems/haptics/haptic_frame.hpp"
#include "cosmems/structure/frame_mesh.hpp"
#include "display_space.hpp"
#include "mesh.hpp"

namespace cosmems::viewer {

/// A node's motion (u [m], theta [rad]) from its carrier's in `frame`: u = u_c + theta_c x r
/// with r its offset from a body's centre, as the model moves it.
Eigen::Matrix<double, 6, 1> NodeMotion(const HapticFrame& frame, const FrameMesh& mesh, int node);

/// The displacement [m] of the point at `xi` (0..1) along `element`'s axis in `frame`: the
/// element's Hermite cubics across, linear along, as BuildDeviceMesh draws it.
Eigen::Vector3d ElementPointMotion(const HapticFrame& frame, const FrameMesh& mesh, int element,
                                   double xi);

/// A device as the display draws it at `frame`'s carrier motion, in `space` (filled after
/// clearing, storage reused frame after frame):
/// - each member element into `members`, `samples_per_element` blocks of its section (thickness
///   along the element's local y, width along its local z) swept along its deflected axis: the
///   element's Hermite cubics in its own axes for the two transverse motions with their slopes,
///   linear in the axial motion and the twist, the section turned by the twist and the slopes;
/// - each body into `bodies`, its block moved by u_c and turned by theta_c (exactly, not
///   linearised: what is drawn is a rigid block whatever the display's scale).
void BuildDeviceMesh(const HapticFrame& frame, const FrameMesh& mesh,
                     const StructureDescription& structure, const DisplaySpace& space,
                     Mesh& members, Mesh& bodies, int samples_per_element = 3);

}  // namespace cosmems::viewer
