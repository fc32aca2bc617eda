#pragma once

#include "cosmems/analysis/pullin_options.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/beam/beam_description.hpp"
#include "cosmems/beam/load_case.hpp"
#include "cosmems/core/material.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/surface/squeeze_film.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/load_time_function.hpp"

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

/// The damping of [effects.damping] when the table is present and enabled; none otherwise.
DampingModel MakeDampingModel(const Scene& scene);

/// The amplitude s(t) that multiplies the loads: loads.time_function, a step when absent.
LoadTimeFunction MakeLoadTimeFunction(const Scene& scene);

/// The Newmark-family parameters of analysis.integrator: Newmark(beta, gamma), Hht(alpha),
/// FromSpectralRadius(rho_inf) or CentralDifference(). The "modal" integrator takes none and
/// gets the average-acceleration rule, which it never uses.
GeneralizedAlphaParameters MakeIntegratorParameters(const SceneAnalysis& analysis);

/// The options of a transient analysis (analysis.type = "transient"): duration, time step,
/// integrator (model.modes modes for "modal"), initial state, time function, damping, and uy
/// recorded at the free end of a cantilever (x = length) or the middle of a bridge (length / 2).
TransientOptions MakeTransientOptions(const Scene& scene);

/// The contact of a validated scene with contact: its gap, stiction with the work of adhesion,
/// and the contact table's separation (0 by default, or a hundredth of the gap when a surface
/// pressure is declared: the pressures grow without bound as the faces close), tolerance and
/// proximity (the core's defaults when absent).
ContactOptions MakeContactOptions(const Scene& scene);

/// The gas of a scene's effects.squeeze_film: its viscosity and mean free path (the core's
/// defaults where absent).
SqueezeFilmOptions MakeSqueezeFilmOptions(const Scene& scene);

/// The pull-in analysis of a validated pullin scene: its electrode (the whole beam unless given),
/// fringing, the travel imposed at the tip or midspan, and voltage_max as the search's bound.
PullInOptions MakePullInOptions(const Scene& scene);

}  // namespace cosmems
