// A release analysis (model set-up excluded): a 400 um silicon cantilever (20 x 2 um section)
// pressed onto the substrate 2 um below and let go, with a work of adhesion of 0.02 J/m^2. It
// peels back to the S shape whose free span s balances the energy release rate,
// s^4 = 3 E t^3 g^2 / (2 Gamma) = (142.0 um)^4. Counters: the free span found, its error against
// that closed form in element lengths and relative, and the Newton iterations.
#include <cmath>

#include "cosmems/analysis/nonlinear_static_analysis.hpp"
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

}  // namespace
}  // namespace cosmems
