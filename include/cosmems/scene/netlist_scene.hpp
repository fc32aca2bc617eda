#pragma once

#include <string>

#include "cosmems/scene/scene.hpp"

namespace cosmems {

/// A validated scene written as a frame scene to edit: the netlist its generator makes (a
/// parametric device's, a cantilever's or a bridge's; a frame's own) as [[structure.nodes]],
/// [[structure.beams]] and [[structure.bodies]], with the scene's material, model, loads and
/// analysis. Run as it is, it gives the scene's results (numbers round-trip exactly). Throws
/// std::invalid_argument naming the key of what a frame scene cannot say yet: a planar beam
/// (model.dimension = 2), a residual axial load, a midspan load.
std::string NetlistScene(const Scene& scene);

}  // namespace cosmems
