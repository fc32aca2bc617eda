// Tang, Nguyen and Howe's folded-flexure resonator built in C++ from its design parameters: its
// stiffness along x against 24 E I / L^3, and its lowest modes with the mass each moves.
#include <cosmems/cosmems.hpp>
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
  return 0;
}
