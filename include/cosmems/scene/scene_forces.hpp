#pragma once

#include <memory>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "cosmems/surface/gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/surface/squeeze_film.hpp"
#include "cosmems/surface/substrate_contact.hpp"

namespace cosmems {

/// The nonlinear forces a validated scene declares, built for its beam model and nothing else: an
/// effect whose table is absent (or disabled) is never constructed, so it costs nothing per step.
/// Composed at run time (ForceSum); ForceTuple composes a fixed set at compile time. The model
/// must outlive the forces.
template <int Dim>
class SceneForces {
 public:
  SceneForces(const BeamModel<Dim>& model, const Scene& scene) {
    const SceneEffects& e = scene.effects;
    if (scene.model.theory == Theory::kStretching) {
      stretching_ = std::make_unique<StretchingForce<Dim>>(model);
      structural_.Add(*stretching_);
    }
    // The gap pressures and the film see no nearer gap than the one contact stops the faces at.
    double separation = 0.0;
    if (e.HasContact()) {
      const ContactOptions contact = MakeContactOptions(scene);
      contact_ = std::make_unique<SubstrateContact<Dim>>(model, contact);
      structural_.Add(*contact_);
      separation = contact.separation;
    }
    const double length = scene.structure.length;
    const double gap = scene.structure.gap.value_or(0.0);
    if (IsOn(e.squeeze_film)) {
      squeeze_film_ =
          std::make_unique<SqueezeFilm<Dim>>(model, MakeSqueezeFilmOptions(scene), gap, separation);
      structural_.Add(*squeeze_film_);
    }
    // A pull-in analysis scales the electrode's pressure itself: it is the analysis's unknown.
    if (IsOn(e.electrostatic) && e.electrostatic->voltage &&
        scene.analysis.type != AnalysisType::kPullin) {
      const ElectrostaticEffect& s = *e.electrostatic;
      AddPressure(model, ElectrostaticPressure{*s.voltage, scene.structure.width, s.fringing},
                  GapSpan{gap, s.electrode_start.value_or(0.0), s.electrode_end.value_or(length)}
                      .WithSeparation(separation));
    }
    if (IsOn(e.casimir)) {
      AddPressure(model, CasimirPressure{}, GapSpan{gap, 0.0, length}.WithSeparation(separation));
    }
    if (IsOn(e.van_der_waals)) {
      AddPressure(model, VanDerWaalsPressure{*e.van_der_waals->hamaker},
                  GapSpan{gap, 0.0, length}.WithSeparation(separation));
    }
    for (NonlinearForce* f :
         {static_cast<NonlinearForce*>(&structural_), static_cast<NonlinearForce*>(&pressures_)}) {
      all_.Add(*f);
    }
  }
  SceneForces(const SceneForces&) = delete;
  SceneForces& operator=(const SceneForces&) = delete;

  /// Every force, or nullptr when the scene declares none (the linear fast path).
  NonlinearForce* All() { return Empty() ? nullptr : &all_; }
  /// Stretching, contact and the gas film (perhaps none).
  ForceSum& structural() { return structural_; }
  /// The gap pressures: electrostatic, Casimir, van der Waals (perhaps none).
  ForceSum& pressures() { return pressures_; }
  bool Empty() const { return structural_.Empty() && pressures_.Empty(); }
  StretchingForce<Dim>* stretching() { return stretching_.get(); }
  SubstrateContact<Dim>* contact() { return contact_.get(); }

 private:
  template <typename Pressure>
  void AddPressure(const BeamModel<Dim>& model, Pressure pressure, const GapSpan& span) {
    auto force = std::make_unique<GapForce<Dim, Pressure>>(model, pressure, span);
    pressures_.Add(*force);
    owned_.push_back(std::move(force));
  }

  std::unique_ptr<StretchingForce<Dim>> stretching_;
  std::unique_ptr<SubstrateContact<Dim>> contact_;
  std::unique_ptr<SqueezeFilm<Dim>> squeeze_film_;
  std::vector<std::unique_ptr<NonlinearForce>> owned_;
  ForceSum structural_, pressures_, all_;
};

}  // namespace cosmems
