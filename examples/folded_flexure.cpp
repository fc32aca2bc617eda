// Tang, Nguyen and Howe's folded-flexure resonator built in C++ from its design parameters: its
// stiffness along x against 24 E I / L^3, its lowest modes with the mass each moves, and its
// shuttle ringing under the same pull applied as a step.
#include <cosmems/analysis/frame_modal_analysis.hpp>
#include <cosmems/analysis/frame_static_analysis.hpp>
#include <cosmems/analysis/frame_transient_analysis.hpp>
#include <cosmems/structure/folded_flexure.hpp>
#include <cosmems/structure/frame_model.hpp>
#include <cstdio>

int main() {
  cosmems::FoldedFlexureDesign design;  // 100 um beams, 2 um wide and thick; 40 um shuttle
  design.material = {160e9, 2330.0, 0.22};
  design.elements = 10;  // per beam
  const cosmems::StructureDescription device = cosmems::FoldedFlexure(design);
  const cosmems::FrameModel model(device);

  cosmems::FrameLoadCase pull;  // 1 uN along x on the shuttle (body 2)
  pull.points.push_back({-1, /*body=*/2, {1e-6, 0.0, 0.0}, {0.0, 0.0, 0.0}});
  const cosmems::FrameStaticSolution statics = cosmems::SolveFrameStatic(model, pull);
  std::printf("shuttle stiffness along x: %.4f N/m (24 E I / L^3 = %.4f N/m)\n",
              1e-6 / statics.bodies[2][0], design.Stiffness());

  cosmems::ModalOptions options;
  options.count = 4;
  const cosmems::FrameModalResult modes = cosmems::SolveFrameModal(model, options);
  for (std::size_t i = 0; i < modes.modal.modes.size(); ++i) {
    const auto& share = modes.participation[i];
    std::printf("mode %zu: %8.2f kHz %-9s  effective mass ux %.3f uy %.3f uz %.3f\n", i + 1,
                modes.modal.modes[i].frequency_hz * 1e-3,
                cosmems::ToString(modes.modal.modes[i].kind), share[0], share[1], share[2]);
  }

  // The pull as a step at t = 0: six modes propagated exactly, the others static; the shuttle
  // overshoots to twice its static deflection.
  cosmems::TransientOptions ring;
  ring.duration = 2e-5;
  ring.time_step = 5e-8;
  ring.path = cosmems::TimePath::kModal;
  ring.modes = 6;
  const cosmems::FrameTransientResult run =
      cosmems::RunFrameTransient(model, pull, ring, {{-1, /*body=*/2}});
  std::printf("step response: shuttle peak %.4g m (2 F / k = %.4g m)\n", run.run.max_abs_output,
              2e-6 / design.Stiffness());
  return 0;
}
