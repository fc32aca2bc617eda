#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace cosmems {

// The [effects] tables of a scene. A table that is present is an effect the scene asks for
// unless it says enabled = false. Parameters the schema gives no default for stay empty when
// absent, so a later solver can tell "not given" from any value.

/// [effects.contact]: unilateral contact with the substrate.
struct ContactEffect {
  bool enabled = true;
  std::optional<double> separation;  ///< m: closest approach of the faces in contact, >= 0
  std::optional<double> tolerance;   ///< m: penetration accepted, > 0
  std::optional<double> proximity;   ///< m: gap below which the beam is "near", > 0
};

/// [effects.stiction]: adhesion to the substrate; implies contact.
struct StictionEffect {
  bool enabled = true;
  std::optional<double> adhesion_energy;  ///< work of adhesion [J/m^2], >= 0
};

/// An entry of effects.electrostatic.electrodes: a rectangle on the substrate under a device.
struct SceneElectrode {
  std::array<double, 2> x = {0.0, 0.0};  ///< m, from x[0] to x[1]
  std::array<double, 2> z = {0.0, 0.0};  ///< m, from z[0] to z[1]
};

/// [effects.electrostatic]: a parallel-plate electrode on the substrate, under the whole beam
/// unless electrode_start / electrode_end are given; under a device, the rectangles of
/// `electrodes`, or one under all of it.
struct ElectrostaticEffect {
  bool enabled = true;
  std::optional<double> voltage;           ///< V
  bool fringing = false;                   ///< add the fringing-field correction
  std::optional<double> electrode_start;   ///< m from the first support, in [0, length]
  std::optional<double> electrode_end;     ///< m from the first support, in [0, length]
  std::vector<SceneElectrode> electrodes;  ///< a device's; empty: one under all of it
  double ac_voltage = 0.0;                 ///< V: a device's transient adds ac sin(2 pi f t)
  std::optional<double> frequency;         ///< Hz, of the alternating part
};

/// [effects.casimir]: the ideal parallel-plate Casimir pressure.
struct CasimirEffect {
  bool enabled = true;
};

/// [effects.van_der_waals]: the van der Waals pressure between beam and substrate.
struct VanDerWaalsEffect {
  bool enabled = true;
  std::optional<double> hamaker;  ///< Hamaker constant [J], > 0
};

/// [effects.damping]: either a quality factor or Rayleigh damping C = alpha M + beta K.
struct DampingEffect {
  bool enabled = true;
  std::optional<double> quality_factor;           ///< Q [-], > 0
  std::optional<std::array<double, 2>> rayleigh;  ///< [alpha 1/s, beta s], each >= 0
};

/// [effects.squeeze_film]: the gas film's damping between beam and substrate.
struct SqueezeFilmEffect {
  bool enabled = true;
  std::optional<double> viscosity;       ///< Pa s, > 0 (default: air at 20 C, 1.81e-5)
  std::optional<double> mean_free_path;  ///< m, >= 0 (default 0: no rarefaction)
};

/// [[effects.combs]]: a comb drive between a body of a device and an anchor (CombDrive).
struct SceneComb {
  std::string body;                                      ///< the body carrying the movable fingers
  int fingers = 0;                                       ///< movable fingers, >= 1
  double gap = 0.0;                                      ///< m, on each side of a finger
  double overlap = 0.0;                                  ///< m, the engagement at rest
  Eigen::Vector3d direction = Eigen::Vector3d::UnitX();  ///< in the substrate plane
  double voltage = 0.0;                                  ///< V
  double ac_voltage = 0.0;          ///< V: a transient adds ac_voltage sin(2 pi frequency t)
  std::optional<double> frequency;  ///< Hz, of the alternating part
};

/// Whether an effect is simulated: its table present and not disabled.
template <typename Effect>
bool IsOn(const std::optional<Effect>& effect) {
  return effect && effect->enabled;
}

/// Every effect a scene declares; an absent table is an effect not simulated.
struct SceneEffects {
  std::optional<ContactEffect> contact;
  std::optional<StictionEffect> stiction;
  std::optional<ElectrostaticEffect> electrostatic;
  std::optional<CasimirEffect> casimir;
  std::optional<VanDerWaalsEffect> van_der_waals;
  std::optional<DampingEffect> damping;
  std::optional<SqueezeFilmEffect> squeeze_film;
  std::vector<SceneComb> combs;  ///< a device's comb drives

  /// Contact with the substrate: [effects.contact], or [effects.stiction], which implies it.
  bool HasContact() const { return IsOn(contact) || IsOn(stiction); }
  /// A pressure across the gap: electrostatic, Casimir or van der Waals.
  bool HasSurfacePressure() const {
    return IsOn(electrostatic) || IsOn(casimir) || IsOn(van_der_waals);
  }
  /// Anything acting through the substrate: contact, a pressure or the gas film.
  bool HasSurfaceEffect() const {
    return HasContact() || HasSurfacePressure() || IsOn(squeeze_film);
  }
};

}  // namespace cosmems
