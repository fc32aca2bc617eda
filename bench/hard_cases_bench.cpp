// The long versions of the hard-case suite (tests/hard_cases): 10^5 stick-release cycles, and the
// released reference cantilever on the linear Newmark path for long runs (1000 elements at 1 ns
// for 10^5 steps) and at every extreme step for each implicit member. The same code as the unit
// tests' shortened runs (tests/hard_cases/*.hpp); the counters are what the README's table of
// hard cases quotes: statuses (0 = ok, see cosmems::Status), drift, largest energies, cycles.
#include <benchmark/benchmark.h>

#include <cmath>

#include "hard_cases/released_cantilever.hpp"
#include "hard_cases/stick_release_cycles.hpp"

namespace cosmems {
namespace {

// 10^5 cycles of the 10-element reference cantilever: laid flat, let go into its S shape, lifted
// off, at rest; 15 steps of 100 us each.
void BM_StickReleaseCycles(benchmark::State& state) {
  const long cycles = state.range(0);
  test::StickReleaseRun run;
  for (auto _ : state) run = test::RunStickReleaseCycles(10, cycles);
  state.counters["status"] = static_cast<double>(run.status);
  state.counters["finite"] = run.finite;
  state.counters["cycles"] = static_cast<double>(run.cycles);
  state.counters["stuck"] = static_cast<double>(run.events.stuck);
  state.counters["releases"] = static_cast<double>(run.events.releases);
  state.counters["span_um"] = 1e6 * run.first_span_m;
  state.counters["span_drift_m"] = run.span_drift_m;
  state.counters["end_drift_m"] = run.end_drift_m;
  // The cycles' largest energies against the first cycle's: 0 when nothing drifts.
  state.counters["max_energy_change"] = run.max_energy_j / run.first_max_energy_j - 1.0;
  state.counters["min_energy_change"] = run.min_cycle_max_energy_j / run.first_max_energy_j - 1.0;
  state.counters["max_energy_over_lift"] = run.max_energy_j / run.lift_energy_j;
  state.counters["newton_per_step"] =
      static_cast<double>(run.iterations) / static_cast<double>(run.steps);
  state.counters["cuts"] = static_cast<double>(run.cuts);
  state.counters["us_per_cycle"] = benchmark::Counter(
      static_cast<double>(run.cycles), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_StickReleaseCycles)
    ->Arg(100000)
    ->ArgName("cycles")
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

GeneralizedAlphaParameters Member(int index) {
  switch (index) {
    case 1:
      return GeneralizedAlphaParameters::Hht(1.0 / 3.0);
    case 2:
      return GeneralizedAlphaParameters::FromSpectralRadius(0.8);
    case 3:
      return GeneralizedAlphaParameters::FromSpectralRadius(0.0);
    default:
      return GeneralizedAlphaParameters::Newmark(0.25, 0.5);
  }
}

// The released cantilever: elements, the step in ns, the member (0 average acceleration, 1 HHT
// alpha = 1/3, 2 generalised-alpha rho_inf = 0.8, 3 rho_inf = 0) and the steps. The energy
// counters are relative to the initial (all strain) energy; max_tip is |u_tip| over its initial
// value.
void BM_ReleasedCantilever(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  const double time_step = 1e-9 * static_cast<double>(state.range(1));
  const long steps = state.range(3);
  test::ReleaseRun run;
  for (auto _ : state) {
    run = test::RunReleasedCantilever(elements, Member(static_cast<int>(state.range(2))), time_step,
                                      steps);
  }
  state.counters["status"] = static_cast<double>(run.status);
  state.counters["finite"] = run.finite;
  state.counters["steps"] = static_cast<double>(run.steps);
  state.counters["max_energy"] = run.max_energy_ratio;
  state.counters["final_energy"] = run.final_energy_ratio;
  state.counters["energy_drift"] = run.final_energy_ratio - 1.0;
  state.counters["max_tip"] = run.max_tip_ratio;
}

// 1000 elements at 1 ns for 10^5 steps (0.1 ms, seven periods of the first mode) by average
// acceleration; then every implicit member at 1 ns, 1 us and 1 ms for 10^4 steps, on 20 and 1000
// elements.
void LongRuns(benchmark::internal::Benchmark* b) {
  b->Args({1000, 1, 0, 100000});
  for (int elements : {20, 1000}) {
    for (long step_ns : {1L, 1000L, 1000000L}) {
      for (int member = 0; member < 4; ++member) b->Args({elements, step_ns, member, 10000});
    }
  }
}
BENCHMARK(BM_ReleasedCantilever)
    ->Apply(LongRuns)
    ->ArgNames({"elements", "dt_ns", "member", "steps"})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmems
