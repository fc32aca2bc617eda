// The lowest vibration modes of the paper's microbridge (Si, 100 x 20 x 2 um, clamped-clamped)
// in 3-D, and how the power-series order changes them on a coarse mesh.
#include <cosmems/analysis/modal_analysis.hpp>
#include <cosmems/beam/beam_model.hpp>
#include <cstdio>

int main() {
  const cosmems::Material silicon{169e9, 2330.0, 0.22};
  const cosmems::RectangularSection section{20e-6, 2e-6};
  for (int order : {0, 1, 2}) {
    const cosmems::BeamModel<3> model(cosmems::MakeStructure(cosmems::StructureKind::kBridge,
                                                             100e-6, silicon, section, 6, order));
    cosmems::ModalOptions options;
    options.count = 5;
    const cosmems::ModalResult result = cosmems::SolveModal(model, options);
    std::printf("series order %d (6 elements):", order);
    for (const cosmems::Mode& mode : result.modes) {
      std::printf("  %.2f kHz %s", mode.frequency_hz * 1e-3, cosmems::ToString(mode.kind));
    }
    std::printf("\n");
  }
  return 0;
}
