// What the safety layer costs a servo tick: SafetyLayer::Filter on an ordinary tick (a press
// with the passivity observer at work) and on one whose inputs must be sanitised (an extreme
// velocity and force every third tick). Header-only: built against another version of
// safety_layer.hpp, the same benchmark compares the two.
#include <benchmark/benchmark.h>

#include <cmath>

#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/safety_layer.hpp"

namespace cosmems {
namespace {

void BM_SafetyFilter(benchmark::State& state) {
  const bool extreme = state.range(0) != 0;
  SafetyLayer layer(SafetyOptions{}, BuiltInSpecs("PHANTOM Omni"));
  DeviceState device;
  ForceCommand command;
  long tick = 0;
  for (auto _ : state) {
    const double phase = 1e-3 * static_cast<double>(tick % 6283);
    device.velocity_m_s = Eigen::Vector3d(0.0, 0.05 * std::sin(phase), 0.01);
    command.force_n = Eigen::Vector3d(0.1, 0.6 * std::cos(phase), 0.0);
    if (extreme && tick % 3 == 0) {
      device.velocity_m_s.y() = 1e200;
      command.force_n.x() = 1e300;
    }
    benchmark::DoNotOptimize(layer.Filter(device, command));
    ++tick;
  }
}
BENCHMARK(BM_SafetyFilter)->Arg(0)->Arg(1)->ArgName("extreme");

}  // namespace
}  // namespace cosmems
