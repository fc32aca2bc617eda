#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include "cosmems/analysis/frame_pullin_analysis.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/structure/frame_stretching_force.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_squeeze_film.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "cosmems/surface/gap_pressures.hpp"

namespace cosmems {

/// The nonlinear forces a validated scene declares: the members' stretching, the Casimir and van
/// der Waals pressures under all of the structure, the gas film, the substrate's contact, and
/// the electrodes' pressure, which each analysis drives its own way (ramped with the loads, held
/// by the pull-in's path, scaled by the voltage in time) and so is kept out of all(). An effect
/// whose table is absent is never built, so it costs nothing. The model must outlive the forces.
class FrameSceneForces {
 public:
  FrameSceneForces(const FrameModel& model, const Scene& scene) {
    const SceneEffects& e = scene.effects;
    if (scene.model.theory == Theory::kStretching) held_.push_back(&stretching_.emplace(model));
    FrameGapOptions substrate{scene.structure.gap.value_or(0.0)};
    if (e.HasContact()) substrate.separation = MakeContactOptions(scene).separation;
    if (IsOn(e.casimir)) {
      pressures_.push_back(&casimir_.emplace(model, CasimirPressure{}, substrate));
    }
    if (IsOn(e.van_der_waals)) {
      pressures_.push_back(&van_der_waals_.emplace(
          model, VanDerWaalsPressure{*e.van_der_waals->hamaker}, substrate));
    }
    elements_ = held_;
    elements_.insert(elements_.end(), pressures_.begin(), pressures_.end());
    for (FrameElementForce* force : elements_) all_.Add(*force);
    if (IsOn(e.squeeze_film)) {
      all_.Add(film_.emplace(model, MakeSqueezeFilmOptions(scene), substrate.gap));
    }
    if (e.HasContact()) all_.Add(contact_.emplace(model, MakeContactOptions(scene)));
    if (IsOn(e.electrostatic)) {
      // At 1 V scaled by V^2 (the pressure is exactly quadratic in V), so that a transient can
      // rescale it to V(t)^2.
      electrodes_.emplace(MakeFrameElectrostaticForce(model, MakeFramePullInOptions(scene), 1.0));
      electrodes_->SetScale(std::pow(e.electrostatic->voltage.value_or(0.0), 2));
    }
  }
  FrameSceneForces(const FrameSceneForces&) = delete;
  FrameSceneForces& operator=(const FrameSceneForces&) = delete;

  /// The forces at rest, element by element (statics and pull-in): stretching and the pressures.
  const std::vector<FrameElementForce*>& elements() const { return elements_; }
  /// Of those, the members' stretching, which holds an unloaded structure at rest.
  const std::vector<FrameElementForce*>& held() const { return held_; }
  /// Of those, the Casimir and van der Waals pressures, which leave no unloaded equilibrium to
  /// start from: statics ramp them with the loads.
  const std::vector<FrameElementForce*>& pressures() const { return pressures_; }
  /// Every force, the film and the contact included (a transient's); the run may add its
  /// electrodes.
  ForceSum& all() { return all_; }
  /// The substrate's contact, for its state and events (nullptr: not declared).
  FrameSubstrateContact* contact() { return contact_ ? &*contact_ : nullptr; }
  /// The electrodes' pressure at the scene's DC voltage (nullptr: not declared); not in all().
  FrameGapForce<ElectrostaticPressure>* electrodes() {
    return electrodes_ ? &*electrodes_ : nullptr;
  }

 private:
  std::optional<FrameStretchingForce> stretching_;
  std::optional<FrameGapForce<CasimirPressure>> casimir_;
  std::optional<FrameGapForce<VanDerWaalsPressure>> van_der_waals_;
  std::optional<FrameSqueezeFilm> film_;
  std::optional<FrameSubstrateContact> contact_;
  std::optional<FrameGapForce<ElectrostaticPressure>> electrodes_;
  std::vector<FrameElementForce*> held_, pressures_, elements_;
  ForceSum all_;
};

}  // namespace cosmems
