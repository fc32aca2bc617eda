#include "scene_fuzz_input.hpp"

#include <cosmems/analysis/frame_pullin_analysis.hpp>
#include <cosmems/analysis/frame_static_analysis.hpp>
#include <cosmems/beam/beam_model.hpp>
#include <cosmems/rod/cosserat_rod.hpp>
#include <cosmems/scene/frame_conversion.hpp>
#include <cosmems/scene/scene_conversion.hpp>
#include <cosmems/scene/scene_error.hpp>
#include <cosmems/scene/scene_loader.hpp>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace cosmems::fuzz {
namespace {

// The model a valid scene builds: its matrices must be finite (the loader refuses dimensions
// and materials the internal units cannot represent). A failure aborts: the fuzzer's finding.
template <int Dim>
void BuildModel(const BeamDescription& description) {
  const BeamModel<Dim> model(description);
  if (!model.Stiffness().data().allFinite() || !model.Mass(0).data().allFinite()) {
    std::fprintf(stderr, "a valid scene built a model with non-finite matrices\n");
    std::abort();
  }
}

// A frame's netlist, its model and loads.
void ConvertFrame(const Scene& scene) {
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure);
  if (!model.Stiffness().data().allFinite() || !model.Mass(0).data().allFinite()) {
    std::fprintf(stderr, "a valid frame scene built a model with non-finite matrices\n");
    std::abort();
  }
  AssembleFrameLoads(model, MakeFrameLoadCase(scene, structure));
  if (IsOn(scene.effects.electrostatic)) {
    MakeFrameElectrostaticForce(model, MakeFramePullInOptions(scene), 1.0);
  }
}

// Every conversion the CLI makes, and the model it builds: a scene the loader accepts must
// convert and build without an error (the loader promises validated scenes).
void Convert(const Scene& scene) {
  if (IsDevice(scene.structure.kind)) {
    ConvertFrame(scene);
    return;
  }
  const BeamDescription description = MakeBeamDescription(scene);
  if (scene.model.theory == Theory::kCosserat) {
    const CosseratRod rod(description);
  } else if (scene.model.dimension == 2) {
    BuildModel<2>(description);
  } else {
    BuildModel<3>(description);
  }
  MakeLoadCase(scene);
  MakeDampingModel(scene);
  MakeLoadTimeFunction(scene);
  MakeIntegratorParameters(scene.analysis);
  if (scene.analysis.type == AnalysisType::kTransient) MakeTransientOptions(scene);
  if (scene.analysis.type == AnalysisType::kPullin) MakePullInOptions(scene);
  if (scene.effects.HasContact()) MakeContactOptions(scene);
}

}  // namespace

void LoadFuzzedScene(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  std::size_t end = input.find('\0');
  const std::string_view toml = input.substr(0, end);
  std::vector<SceneOverride> overrides;
  try {
    while (end != std::string_view::npos) {
      const std::size_t next = input.find('\0', end + 1);
      overrides.push_back(SceneOverride::Parse(std::string(input.substr(end + 1, next - end - 1))));
      end = next;
    }
    Convert(LoadSceneText(toml, "fuzz", overrides));
  } catch (const SceneError&) {
    // The clear error bad input deserves.
  }
}

}  // namespace cosmems::fuzz
