#include "model_settings.hpp"

#include <cmath>
#include <cstdio>

namespace cosmems::viewer {

ModelSettings ModelSettings::FromScene(const Scene& scene, const HapticPhysicsOptions& physics) {
  ModelSettings s;
  const SceneStructure& st = scene.structure;
  s.kind = st.kind;
  s.length_m = st.length;
  s.width_m = st.width;
  s.thickness_m = st.thickness;
  s.design = DesignParameters(scene);
  s.substrate = st.gap.has_value();
  s.gap_m = st.gap.value_or(st.thickness);
  s.young_modulus_pa = scene.material.young_modulus;
  s.density_kg_m3 = scene.material.density;
  s.elements = scene.model.elements;
  s.theory = scene.model.theory;
  s.series_order = scene.model.series_order;
  const SceneEffects& e = scene.effects;
  s.contact = IsOn(e.contact);
  s.stiction = IsOn(e.stiction);
  if (e.stiction && e.stiction->adhesion_energy)
    s.adhesion_energy_j_m2 = *e.stiction->adhesion_energy;
  s.electrostatic = IsOn(e.electrostatic);
  if (e.electrostatic && e.electrostatic->voltage) s.voltage_v = *e.electrostatic->voltage;
  s.casimir = IsOn(e.casimir);
  s.van_der_waals = IsOn(e.van_der_waals);
  if (e.van_der_waals && e.van_der_waals->hamaker) s.hamaker_j = *e.van_der_waals->hamaker;
  s.physics = physics;
  return s;
}

std::vector<SceneOverride> ModelSettings::ToOverrides() const {
  auto flag = [](bool on) { return std::string(on ? "true" : "false"); };
  const bool device = IsDevice(kind);
  std::vector<SceneOverride> out = {{"structure.kind", ToString(kind)}};
  if (!device) {
    out.push_back({"structure.length", TomlFloat(length_m)});
    out.push_back({"structure.width", TomlFloat(width_m)});
  }
  for (const DesignParameter& p : design) {
    out.push_back({"structure." + p.key,
                   p.integer ? std::to_string(std::lround(p.value)) : TomlFloat(p.value)});
  }
  out.insert(out.end(), {
                            {"structure.thickness", TomlFloat(thickness_m)},
                            {"material.young_modulus", TomlFloat(young_modulus_pa)},
                            {"material.density", TomlFloat(density_kg_m3)},
                            {"model.elements", std::to_string(elements)},
                            {"model.theory", ToString(theory)},
                            {"model.series_order", std::to_string(series_order)},
                        });
  // A gap can be given, not taken away: a scene without one gets it once the substrate is on.
  if (substrate) out.push_back({"structure.gap", TomlFloat(gap_m)});
  // Every effect's table with its parameters, on or off, so the loader checks them either way.
  out.push_back({"effects.contact.enabled", flag(contact)});
  out.push_back({"effects.stiction.enabled", flag(stiction)});
  out.push_back({"effects.stiction.adhesion_energy", TomlFloat(adhesion_energy_j_m2)});
  out.push_back({"effects.electrostatic.enabled", flag(electrostatic)});
  out.push_back({"effects.electrostatic.voltage", TomlFloat(voltage_v)});
  out.push_back({"effects.casimir.enabled", flag(casimir)});
  out.push_back({"effects.van_der_waals.enabled", flag(van_der_waals)});
  out.push_back({"effects.van_der_waals.hamaker", TomlFloat(hamaker_j)});
  return out;
}

std::string TomlFloat(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  std::string out = text;
  // "%g" writes whole numbers without a point, which TOML reads as integers.
  if (std::isfinite(value) && out.find_first_of(".e") == std::string::npos) out += ".0";
  return out;
}

}  // namespace cosmems::viewer
