#pragma once

#include <string>

#include "cosmems/scene/scene.hpp"

namespace cosmems {

/// A validated device scene (IsDevice(structure.kind)) written as a frame scene to edit: the
/// netlist its generator makes (or its own, for a frame) as [[structure.nodes]],
/// [[structure.beams]] and [[structure.bodies]], with the scene's material, model, loads and
/// analysis. Run as it is, it gives the device's results (numbers round-trip exactly).
std::string NetlistScene(const Scene& scene);

}  // namespace cosmems
