#pragma once

// A step benchmark's own time per step, for the counters derived from it (x_flop_time, x_dense):
// Google Benchmark's figures are not readable inside the benchmark that makes them.

#include <benchmark/benchmark.h>

#include <chrono>

namespace cosmems::bench {

// The time per step [ns] of `count` calls of `step`, run back to back.
template <typename Step>
double TimeSteps(long count, Step&& step) {
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < count; ++i) step();
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start)
             .count() /
         static_cast<double>(count);
}

// Runs the benchmark's loop over `step` and returns its time per step [ns].
template <typename Step>
double TimedLoop(benchmark::State& state, Step&& step) {
  const auto start = std::chrono::steady_clock::now();
  for (auto _ : state) step();
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start)
             .count() /
         static_cast<double>(state.iterations());
}

}  // namespace cosmems::bench
