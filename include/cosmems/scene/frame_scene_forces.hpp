#pragma once

#include <optional>
#include <vector>

#include "cosmems/beam/force_sum.hpp"
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

/// The nonlinear forces a validated device scene declares besides its electrodes (which each
/// analysis drives its own way: ramped with the loads, held by the pull-in's path, scaled by the
/// voltage in time): the members' stretching, the Casimir and van der Waals pressures under all
/// of the device, the gas film and the substrate's contact. An effect whose table is absent is
/// never built, so it costs nothing. The model must outlive the forces.
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

 private:
  std::optional<FrameStretchingForce> stretching_;
  std::optional<FrameGapForce<CasimirPressure>> casimir_;
  std::optional<FrameGapForce<VanDerWaalsPressure>> van_der_waals_;
  std::optional<FrameSqueezeFilm> film_;
  std::optional<FrameSubstrateContact> contact_;
  std::vector<FrameElementForce*> held_, pressures_, elements_;
  ForceSum all_;
};

}  // namespace cosmems
