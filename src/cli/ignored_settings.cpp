#include "ignored_settings.hpp"

#include "cosmems/scene/scene_conversion.hpp"

namespace cosmems::internal {

std::vector<std::string> IgnoredSettingWarnings(const Scene& scene) {
  std::vector<std::string> warnings;
  const AnalysisType type = scene.analysis.type;
  if (type != AnalysisType::kStatic && type != AnalysisType::kModal &&
      type != AnalysisType::kBuckling && type != AnalysisType::kPullin &&
      type != AnalysisType::kRelease) {
    return warnings;
  }
  const std::string unchanged = std::string(" does not change a ") + ToString(type) + " analysis: ";
  const std::optional<DampingEffect>& damping = scene.effects.damping;
  if (IsOn(damping)) {
    warnings.push_back("effects.damping" + unchanged +
                       (type == AnalysisType::kModal
                            ? "its frequencies and modes are those of the undamped beam"
                            : "damping acts in transient analyses only"));
  }
  if (IsOn(scene.effects.squeeze_film)) {
    warnings.push_back("effects.squeeze_film" + unchanged +
                       "the gas film resists motion, in transient and haptic analyses only");
  }
  if (scene.model.modes > 0) {
    warnings.push_back("model.modes = " + std::to_string(scene.model.modes) + unchanged +
                       "modal reduction applies to transient analyses only (analysis.integrator "
                       "= \"modal\")");
  }
  if (scene.loads.time_function) {
    warnings.push_back("loads.time_function = \"" +
                       std::string(ToString(scene.loads.time_function->kind)) + "\"" + unchanged +
                       "it sets how the loads vary in transient analyses only");
  }
  if (type == AnalysisType::kPullin && !MakeLoadCase(scene).Empty()) {
    warnings.push_back("loads" + unchanged +
                       "the pull-in voltage is the unloaded beam's (the electrode alone pulls it)");
  }
  const std::optional<ElectrostaticEffect>& electrode = scene.effects.electrostatic;
  if (type == AnalysisType::kPullin && electrode && electrode->voltage) {
    warnings.push_back("effects.electrostatic.voltage" + unchanged +
                       "the voltage is what the analysis finds");
  }
  if (type == AnalysisType::kBuckling && scene.model.theory != Theory::kLinear) {
    warnings.push_back("model.theory = \"" + std::string(ToString(scene.model.theory)) + "\"" +
                       unchanged +
                       "the critical load is where the straight beam bifurcates, the same in "
                       "every theory (it is computed from the linear beam)");
  }
  if (type == AnalysisType::kBuckling && !MakeLoadCase(scene).Empty()) {
    warnings.push_back("loads" + unchanged +
                       "the critical load is the beam's own; structure.axial_load is part of it");
  }
  return warnings;
}

}  // namespace cosmems::internal
