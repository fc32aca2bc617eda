// Tang, Nguyen and Howe's folded-flexure resonator built in C++ as a netlist: a shuttle on four
// folded beam pairs whose outer ends two rigid trusses join. Its stiffness along x against
// 24 E I / L^3, and its lowest modes with the mass each moves.
#include <cosmems/cosmems.hpp>
#include <cstdio>
#include <string>

int main() {
  const cosmems::Material poly{160e9, 2330.0, 0.22};
  const cosmems::RectangularSection beam{2e-6, 2e-6};  // width, thickness
  const double length = 100e-6, half = 20e-6;
  cosmems::StructureDescription s;
  auto node = [&](const std::string& name, double x, double z, cosmems::Support support) {
    s.nodes.push_back({name, {x, 0.0, z}, cosmems::AnchorOf(support)});
    return static_cast<int>(s.nodes.size()) - 1;
  };
  std::vector<int> shuttle;
  for (int side_z : {-1, 1}) {
    std::vector<int> truss;
    for (int side_x : {-1, 1}) {
      const std::string tag = std::to_string(side_x) + std::to_string(side_z);
      const int anchor =
          node("anchor" + tag, 12e-6 * side_x, half * side_z, cosmems::Support::kClamped);
      const int joint = node("joint" + tag, 16e-6 * side_x, half * side_z, cosmems::Support::kFree);
      const int in =
          node("in" + tag, 12e-6 * side_x, (half + length) * side_z, cosmems::Support::kFree);
      const int out =
          node("out" + tag, 16e-6 * side_x, (half + length) * side_z, cosmems::Support::kFree);
      s.members.push_back({anchor, in, poly, beam, 10});  // inner beam
      s.members.push_back({out, joint, poly, beam, 10});  // outer beam
      shuttle.push_back(joint);
      truss.push_back(in);
      truss.push_back(out);
    }
    s.bodies.push_back({side_z < 0 ? "truss_low" : "truss_high",
                        {0.0, 0.0, (half + length + 2e-6) * side_z},
                        {40e-6, 2e-6, 4e-6},
                        poly.density,
                        truss});
  }
  s.bodies.push_back({"shuttle", {0.0, 0.0, 0.0}, {40e-6, 2e-6, 40e-6}, poly.density, shuttle});
  const cosmems::FrameModel model(s);

  cosmems::FrameLoadCase pull;
  pull.points.push_back({-1, /*body=*/2, {1e-6, 0.0, 0.0}, {0.0, 0.0, 0.0}});
  const cosmems::FrameStaticSolution statics = cosmems::SolveFrameStatic(model, pull);
  const double k = 24 * poly.young_modulus * beam.SecondMomentY() / (length * length * length);
  std::printf("shuttle stiffness along x: %.4f N/m (24 E I / L^3 = %.4f N/m)\n",
              1e-6 / statics.bodies[2][0], k);

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
