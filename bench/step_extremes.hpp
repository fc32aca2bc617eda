#pragma once

// Per-step tails for the step benchmarks: Google Benchmark reports the mean of many steps; a
// haptic loop cares about the slowest. Each of 20000 steps is timed on its own with
// steady_clock, whose own cost (about 20 ns here) is included in the figures.

#include <benchmark/benchmark.h>

#include <chrono>
#include <vector>

#include "cosmems/analysis/step_timing.hpp"

namespace cosmems::bench {

template <typename Step>
void RecordStepExtremes(benchmark::State& state, Step&& step) {
  std::vector<double> us(20000);
  for (double& sample : us) {
    const auto start = std::chrono::steady_clock::now();
    step();
    sample =
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  }
  const StepTiming timing = StepTiming::From(std::move(us));
  state.counters["p50_ns"] = 1e3 * timing.median_us;
  state.counters["p99_ns"] = 1e3 * timing.p99_us;
  state.counters["max_ns"] = 1e3 * timing.max_us;
}

}  // namespace cosmems::bench
