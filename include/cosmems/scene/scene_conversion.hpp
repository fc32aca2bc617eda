#pragma once

#include "cosmems/beam/beam_description.hpp"
#include "cosmems/beam/load_case.hpp"
#include "cosmems/core/material.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems {

// From a validated Scene (as LoadScene returns it) to the core's descriptions, in SI.

/// The material the beam bends with: E, or the plate modulus E / (1 - nu^2) when
/// plate_modulus is set. The core derives the torsional shear modulus from the same E.
Material EffectiveMaterial(const SceneMaterial& material);

/// The beam of `scene.model.elements` equal elements, clamped at x = 0 (and at x = length for
/// a bridge), with the scene's series order.
BeamDescription MakeBeamDescription(const Scene& scene);

/// The scene's loads: tip force and moment at x = length, midspan force at length / 2, and the
/// distributed load over the whole beam. Zero loads are left out.
LoadCase MakeLoadCase(const Scene& scene);

}  // namespace cosmems
