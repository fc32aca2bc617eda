// Prints the relative error of the first four bending frequencies of the reference cantilever
// and bridge (planar model) against the roots of cos x cosh x = -/+1, for meshes of 2 ... 40
// elements and series orders 0 ... 3: what each term of the power series buys on a mesh. Then
// the same for two frames with junctions (structure/frame_convergence.hpp) against their exact
// frequencies, with the observed rate in h of the four modes' largest error.
#include <algorithm>
#include <cmath>
#include <cosmems/cosmems.hpp>
#include <cstdio>

#include "structure/frame_convergence.hpp"  // the frames and their exact frequencies
#include "test_beams.hpp"  // the reference beam and the frequency equation of the tests

namespace {

void PrintFrameConvergence() {
  constexpr int kModes = 4;
  for (const cosmems::test::ConvergenceFrame& frame : cosmems::test::ConvergenceFrames()) {
    const std::vector<double> exact = cosmems::test::ExactFrequencies(frame, kModes);
    std::printf("%s: relative error of modes 1-4 (exact %.6g ... %.6g Hz), largest, rate\n",
                frame.name.c_str(), exact.front(), exact.back());
    std::printf("%9s %6s %10s %10s %10s %10s %10s %6s\n", "el/member", "order", "mode 1", "mode 2",
                "mode 3", "mode 4", "largest", "rate");
    for (int order = 0; order <= 2; ++order) {
      double previous = 0.0;
      for (int elements : {1, 2, 4, 8, 16}) {
        const std::vector<double> hz =
            cosmems::test::ModelFrequencies(frame, elements, order, kModes);
        std::printf("%9d %6d", elements, order);
        double largest = 0.0;
        for (int i = 0; i < kModes; ++i) {
          const double e = std::abs(hz.at(i) - exact[i]) / exact[i];
          largest = std::max(largest, e);
          std::printf(" %10.1e", e);
        }
        std::printf(" %10.1e", largest);
        if (previous > 0.0) std::printf(" %6.2f", std::log2(previous / largest));
        std::printf("\n");
        previous = largest;
      }
    }
  }
}

}  // namespace

int main() {
  const cosmems::Material silicon = cosmems::test::Silicon();
  const cosmems::RectangularSection section = cosmems::test::ReferenceSection();
  const double length = cosmems::test::kReferenceLength;
  const double ei = silicon.young_modulus * section.SecondMomentZ();
  const double rho_a = silicon.density * section.Area();
  for (const auto kind : {cosmems::StructureKind::kCantilever, cosmems::StructureKind::kBridge}) {
    const bool bridge = kind == cosmems::StructureKind::kBridge;
    std::printf("%s: relative error of modes 1-4\n", bridge ? "bridge" : "cantilever");
    std::printf("%9s %6s %10s %10s %10s %10s\n", "elements", "order", "mode 1", "mode 2", "mode 3",
                "mode 4");
    for (int order = 0; order <= 3; ++order) {
      for (int elements : {2, 4, 8, 20, 40}) {
        const cosmems::BeamModel<2> model(
            cosmems::MakeStructure(kind, length, silicon, section, elements, order));
        cosmems::ModalOptions options;
        options.count = 4;
        const cosmems::ModalResult result = cosmems::SolveModal(model, options);
        std::printf("%9d %6d", elements, order);
        for (std::size_t i = 0; i < result.modes.size(); ++i) {
          const double x =
              cosmems::test::FrequencyRoot(static_cast<int>(i) + 1, bridge ? 1.0 : -1.0);
          const double exact = cosmems::test::BendingFrequency(x, length, ei, rho_a);
          std::printf(" %10.1e", std::abs(result.modes[i].frequency_hz - exact) / exact);
        }
        std::printf("%s\n", result.status == cosmems::Status::kOk ? "" : "  (not converged)");
      }
    }
  }
  PrintFrameConvergence();
  return 0;
}
