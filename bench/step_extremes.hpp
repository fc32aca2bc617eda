#pragma once

// Per-step tails for the step benchmarks: Google Benchmark reports the mean of many steps; a
// haptic loop cares about the slowest. Each of 20000 steps is timed on its own with
// steady_clock, whose own cost (about 20 ns here) is included in the figures.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace cosmems::bench {

template <typename Step>
void RecordStepExtremes(benchmark::State& state, Step&& step) {
  constexpr int kSamples = 20000;
  std::vector<double> ns(kSamples);
  for (double& sample : ns) {
    const auto start = std::chrono::steady_clock::now();
    step();
    sample =
        std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  }
  std::sort(ns.begin(), ns.end());
  state.counters["p50_ns"] = ns[kSamples / 2];
  state.counters["p99_ns"] = ns[kSamples * 99 / 100];
  state.counters["max_ns"] = ns.back();
}

}  // namespace cosmems::bench
