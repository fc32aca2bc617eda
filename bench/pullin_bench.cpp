// A pull-in analysis from scratch (model set-up excluded): the reference cantilever and bridge
// (200 um, 2 um gap, electrode under the whole beam, planar, series order 1), the bridge also
// with mid-plane stretching. Counters: the voltage found, the solves and Newton iterations.
#include <optional>
#include <string>

#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

void BM_PullIn(benchmark::State& state) {
  const auto kind = static_cast<StructureKind>(state.range(1));
  const BeamModel<2> model(bench::ReferenceBeam(kind, static_cast<int>(state.range(0)), 1));
  const bool stretch = state.range(2) != 0;
  std::optional<StretchingForce<2>> stretching;
  if (stretch) stretching.emplace(model);
  PullInOptions options;
  options.electrode = {2e-6, 0.0, 200e-6};
  options.control_x = kind == StructureKind::kCantilever ? 200e-6 : 100e-6;
  PullInResult result;
  for (auto _ : state) {
    result = SolvePullIn(model, options, stretching ? &*stretching : nullptr);
    if (result.status != Status::kOk) state.SkipWithError("pull-in failed");
  }
  state.counters["voltage_v"] = result.voltage_v;
  state.counters["solves"] = result.solves;
  state.counters["newton"] = result.iterations;
  state.SetLabel(std::string(kind == StructureKind::kCantilever ? "cantilever" : "bridge") +
                 (stretch ? ", stretching" : ""));
}
BENCHMARK(BM_PullIn)
    ->Args({20, static_cast<int>(StructureKind::kCantilever), 0})
    ->Args({40, static_cast<int>(StructureKind::kBridge), 0})
    ->Args({40, static_cast<int>(StructureKind::kBridge), 1})
    ->ArgNames({"elements", "kind", "stretching"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
