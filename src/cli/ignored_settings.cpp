#include "ignored_settings.hpp"

#include "cosmems/scene/scene_conversion.hpp"

namespace cosmems::internal {
namespace {

// The haptic analysis touches the structure with the probe alone (HapticSession builds its
// physics without loads); only its modal integrator takes the damping, as the modes' ratios.
void AddHapticWarnings(const Scene& scene, const std::string& unchanged,
                       std::vector<std::string>& warnings) {
  if (!MakeLoadCase(scene).Empty() || !scene.loads.points.empty()) {
    warnings.push_back("loads" + unchanged + "the hand's probe is the only load on the structure");
  }
  if (IsOn(scene.effects.damping) && scene.analysis.integrator != Integrator::kModal) {
    warnings.push_back("effects.damping" + unchanged +
                       "the touched structure is damped by the squeeze film only (the tick's "
                       "integrator removes the vibrations it does not resolve; the modal "
                       "integrator takes it)");
  }
}

// Static, modal, buckling, pull-in and release analyses: no time, so no damping, time function
// or modal stepping, and the loads are not what a pull-in or buckling analysis solves for.
void AddTimelessWarnings(const Scene& scene, const std::string& unchanged,
                         std::vector<std::string>& warnings) {
  const AnalysisType type = scene.analysis.type;
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
}

}  // namespace

std::vector<std::string> IgnoredSettingWarnings(const Scene& scene) {
  std::vector<std::string> warnings;
  const AnalysisType type = scene.analysis.type;
  const std::string unchanged = std::string(" does not change a ") + ToString(type) + " analysis: ";
  if (type == AnalysisType::kHaptic) {
    AddHapticWarnings(scene, unchanged, warnings);
  } else if (type != AnalysisType::kTransient) {
    AddTimelessWarnings(scene, unchanged, warnings);
  }
  if (type != AnalysisType::kTransient && scene.loads.time_function) {
    warnings.push_back("loads.time_function = \"" +
                       std::string(ToString(scene.loads.time_function->kind)) + "\"" + unchanged +
                       "it sets how the loads vary in transient analyses only");
  }
  if (type != AnalysisType::kHaptic && scene.device) {
    warnings.push_back("device" + unchanged + "[device] is the stylus of a haptic analysis only");
  }
  return warnings;
}

}  // namespace cosmems::internal
