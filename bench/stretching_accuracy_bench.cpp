// What accuracy costs for a stretching microbridge: the reference bridge (200 um, planar, series
// order 1) under a uniform load that presses it five thicknesses deep, solved by Newton from rest
// against the element count; counters err_midspan and err_tension are the relative errors
// against the exact tie-beam solution (tests/beam/stretched_bridge.hpp), beside the solve time.
#include <cmath>

#include "beam/stretched_bridge.hpp"
#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

void BM_StretchingAccuracy(benchmark::State& state) {
  const BeamModel<2> model(
      bench::ReferenceBeam(StructureKind::kBridge, static_cast<int>(state.range(0)), 1));
  StretchingForce<2> force(model);
  LoadCase loads;
  loads.distributed = Eigen::Vector3d(0.0, -100.0, 0.0);  // N/m
  NonlinearStaticSolution solution;
  for (auto _ : state) {
    solution = SolveNonlinearStatic(model, force, loads);
    if (solution.status != Status::kOk) state.SkipWithError("solve failed");
  }
  const double length = model.description().Length();
  const ElementSpec& spec = model.description().elements.front();
  const double ei = spec.material.young_modulus * spec.section.SecondMomentZ();
  const double ea = spec.material.young_modulus * spec.section.Area();
  const test::StretchedBridge exact =
      test::SolveStretchedBridge(length, ei, ea, loads.distributed.y(), 0.0);
  const double midspan = BeamField<2>(model, solution.displacement).At(0.5 * length)[1];
  const double tension = force.AxialForce(solution.displacement) * model.units().force;
  state.counters["err_midspan"] = std::abs(midspan / exact.midspan - 1.0);
  state.counters["err_tension"] = std::abs(tension / exact.tension - 1.0);
}
BENCHMARK(BM_StretchingAccuracy)
    ->Arg(5)
    ->Arg(10)
    ->Arg(20)
    ->Arg(40)
    ->Arg(80)
    ->Arg(160)
    ->ArgName("elements")
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
