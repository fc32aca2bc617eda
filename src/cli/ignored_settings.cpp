#include "ignored_settings.hpp"

#include "cosmems/scene/scene_conversion.hpp"

namespace cosmems::internal {

std::vector<std::string> IgnoredSettingWarnings(const Scene& scene) {
  std::vector<std::string> warnings;
  const AnalysisType type = scene.analysis.type;
  if (type != AnalysisType::kStatic && type != AnalysisType::kModal &&
      type != AnalysisType::kBuckling) {
    return warnings;
  }
  const std::string unchanged = std::string(" does not change a ") + ToString(type) + " analysis: ";
  const std::optional<DampingEffect>& damping = scene.effects.damping;
  if (damping && damping->enabled) {
    warnings.push_back("effects.damping" + unchanged +
                       (type == AnalysisType::kModal
                            ? "its frequencies and modes are those of the undamped beam"
                            : "damping acts in transient analyses only"));
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
  if (type == AnalysisType::kBuckling && !MakeLoadCase(scene).Empty()) {
    warnings.push_back("loads" + unchanged +
                       "the critical load is the beam's own; structure.axial_load is part of it");
  }
  return warnings;
}

}  // namespace cosmems::internal
