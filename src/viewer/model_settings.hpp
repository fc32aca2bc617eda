#pragma once

#include <string>
#include <vector>

#include "cosmems/haptics/haptic_physics.hpp"
#include "cosmems/scene/design_parameters.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scene/scene_loader.hpp"

namespace cosmems::viewer {

/// What the panel edits: the structure (a beam's sizes, or a parametric device's design keys),
/// the material, the model, the effects with their parameters and the physics of the haptic
/// tick, in SI. The edits reach the model as `--set`
/// overrides on the scene, so the scene loader validates them exactly as it validates a file
/// and names the key and value it refuses.
struct ModelSettings {
  StructureKind kind = StructureKind::kCantilever;
  double length_m = 0.0, width_m = 0.0, thickness_m = 0.0;  ///< a device: its thickness alone
  std::vector<DesignParameter> design;  ///< a parametric device's design keys (SI)
  bool substrate = false;               ///< a substrate at gap_m below the beam
  double gap_m = 0.0;
  double young_modulus_pa = 0.0, density_kg_m3 = 0.0;
  int elements = 0;
  Theory theory = Theory::kLinear;
  int series_order = 0;
  bool contact = false, stiction = false;
  double adhesion_energy_j_m2 = 0.02;
  bool electrostatic = false;
  double voltage_v = 5.0;
  bool casimir = false;
  bool van_der_waals = false;
  double hamaker_j = 1e-19;
  /// The haptic tick's generalised-alpha integrator.
  HapticPhysicsOptions physics;

  /// The settings of a loaded scene (parameters it leaves out keep the defaults above).
  static ModelSettings FromScene(const Scene& scene, const HapticPhysicsOptions& physics);
  /// Every setting but the physics as a `--set` override, table by table: a device's without the
  /// beam's sizes (which it does not read).
  std::vector<SceneOverride> ToOverrides() const;
};

/// `value` as a TOML float that reads back to the same double.
std::string TomlFloat(double value);

}  // namespace cosmems::viewer
