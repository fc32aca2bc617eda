#pragma once

// The yardstick of "a step at the speed of its arithmetic": how long this machine, with this
// build's flags, takes for one floating-point operation when operations do not wait on each
// other (eight independent multiply-add chains, so that latency is hidden as in a step whose
// modes or rows are independent). A step of N flops then costs at least N times this.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>

namespace cosmems::bench {

/// `rounds` rounds of x = x a + b on each of the eight chains: 16 flops a round, none waiting on
/// another chain's.
inline void MultiplyAddChains(std::array<double, 8>& chain, double a, double b, long rounds) {
  for (long round = 0; round < rounds; ++round) {
    for (double& x : chain) x = x * a + b;
  }
}

inline double NanosecondsPerFlop() {
  static const double rate = [] {
    constexpr long kRounds = 1 << 22;
    double best = 1e9;
    for (int run = 0; run < 5; ++run) {
      std::array<double, 8> chain{1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7};
      double a = 0.999999, b = 1e-9;
      benchmark::DoNotOptimize(a);
      benchmark::DoNotOptimize(b);
      const auto start = std::chrono::steady_clock::now();
      MultiplyAddChains(chain, a, b, kRounds);
      const double ns =
          std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start)
              .count();
      benchmark::DoNotOptimize(chain.data());
      benchmark::ClobberMemory();
      best = std::min(best, ns / (2.0 * 8.0 * kRounds));
    }
    return best;
  }();
  return rate;
}

/// Counters for a step of `flops` operations that took `step_ns`: the count, its time at the
/// machine's rate, and the step's multiple of that time.
inline void RecordArithmetic(benchmark::State& state, double flops, double step_ns) {
  const double yardstick = flops * NanosecondsPerFlop();
  state.counters["flops"] = flops;
  state.counters["flop_time_ns"] = yardstick;
  state.counters["x_flop_time"] = step_ns / yardstick;
}

}  // namespace cosmems::bench
