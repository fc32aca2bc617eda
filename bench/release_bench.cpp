// A release analysis (model set-up excluded): a 400 um silicon cantilever (20 x 2 um section)
// pressed onto the substrate 2 um below and let go, with a work of adhesion of 0.02 J/m^2. It
// peels back to the S shape whose free span s balances the energy release rate,
// s^4 = 3 E t^3 g^2 / (2 Gamma) = (142.0 um)^4. Counters: the free span found, its error against
// that closed form in element lengths and relative, and the Newton iterations.
#include <cmath>

#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/structure/serpentine.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

constexpr double kLength = 400e-6, kGap = 2e-6, kGamma = 0.02;

void BM_Release(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, kLength,
                                         Material{169e9, 2330.0, 0.22},
                                         RectangularSection{20e-6, 2e-6}, elements, 0));
  ContactOptions options;
  options.gap = kGap;
  options.stiction = true;
  options.adhesion_energy = kGamma;
  ContactSummary summary;
  int iterations = 0;
  for (auto _ : state) {
    SubstrateContact<2> contact(model, options);
    contact.StickAll();
    const NonlinearStaticSolution solution = SolveNonlinearStatic(model, contact, LoadCase{});
    if (solution.status != Status::kOk) state.SkipWithError("release failed");
    summary = contact.Summary();
    iterations = solution.iterations;
  }
  const double exact = std::pow(3.0 * 169e9 * 8e-18 * kGap * kGap / (2.0 * kGamma), 0.25);
  state.counters["span_um"] = 1e6 * summary.detached_length_m;
  state.counters["error_elements"] = (summary.detached_length_m - exact) / (kLength / elements);
  state.counters["error_relative"] = (summary.detached_length_m - exact) / exact;
  state.counters["newton"] = iterations;
}
BENCHMARK(BM_Release)
    ->Arg(25)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->ArgName("elements")
    ->Unit(benchmark::kMicrosecond);

// A device's release (model set-up excluded): pressed onto the substrate all over and let go
// (FrameSubstrateContact from PressedDisplacement()). `device` 0: the cantilever above as a member
// of a frame, 100 elements (its free span is the beam's, node for node); 1: the serpentine plate
// (SerpentineDesign's defaults: 4 springs of 4 turns, 4 elements a segment) over a 2 um gap at
// Gamma = 1e-3 J/m^2, its springs stuck along their spans and the plate held. Counters: whether
// it stays stuck, the member's free span, the Newton iterations.
void BM_DeviceRelease(benchmark::State& state) {
  const bool serpentine = state.range(0) == 1;
  StructureDescription structure;
  if (serpentine) {
    structure = Serpentine(SerpentineDesign{});
  } else {
    structure.nodes = {{"clamp", Eigen::Vector3d::Zero(), AnchorOf(Support::kClamped)},
                       {"tip", Eigen::Vector3d(kLength, 0.0, 0.0), AnchorMask{}}};
    structure.members.push_back({0, 1, Material{169e9, 2330.0, 0.22},
                                 RectangularSection{20e-6, 2e-6}, 100, Eigen::Vector3d::UnitY()});
  }
  const FrameModel model(structure);
  ContactOptions options;
  options.gap = kGap;
  options.stiction = true;
  options.adhesion_energy = serpentine ? 1e-3 : kGamma;
  NonlinearStaticOptions solve_options;
  solve_options.newton.max_settles = 100000;
  bool stuck = false;
  double span = 0.0;
  int iterations = 0;
  for (auto _ : state) {
    FrameSubstrateContact contact(model, options);
    contact.StickAll();
    solve_options.start = contact.PressedDisplacement();
    NonlinearStaticSolve solve(model.Stiffness(), contact, solve_options, nullptr);
    const NonlinearStaticSolution solution =
        solve.Solve(Eigen::VectorXd::Zero(model.FreeDofCount()));
    if (solution.status != Status::kOk) state.SkipWithError("release failed");
    stuck = contact.Summary().Stuck();
    span = contact.MemberSummary(0).detached_length_m;
    iterations = solution.iterations;
  }
  state.counters["stuck"] = stuck;
  if (!serpentine) state.counters["span_um"] = 1e6 * span;
  state.counters["newton"] = iterations;
  state.counters["dofs"] = model.FreeDofCount();
}
BENCHMARK(BM_DeviceRelease)->Arg(0)->Arg(1)->ArgName("device")->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
