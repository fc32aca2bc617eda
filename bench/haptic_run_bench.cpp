// The default haptic scene (cantilever-haptic: the 20-element reference cantilever with contact,
// stiction and the Casimir force, pressed by the scripted stylus) run for 10 s paced on the wall
// clock at 1 kHz, the physics on its own thread, as `cosmems run cantilever-haptic` runs it.
// Counters: the servo loop's achieved rate, its tick compute times and deadline misses, and the
// physics thread's tick times; the servo ticks' compute-time histogram goes to stderr.
// BM_BareTimer is the machine's floor: the same paced real-time thread doing no work at all, so
// that late wake-ups the machine itself causes are told apart from the loop's.
#include <benchmark/benchmark.h>

#include <chrono>
#include <iostream>
#include <thread>

#include "cosmems/haptics/loop_stats.hpp"
#include "cosmems/haptics/periodic_deadline.hpp"
#include "cosmems/haptics/realtime_thread.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "cosmems/session/haptic_session.hpp"

namespace cosmems {
namespace {

void PrintHistogram(const LoopStats& s, const char* title) {
  std::cerr << title << " compute time histogram (1 us bins, non-empty only):\n";
  for (int i = 0; i < LoopStats::kBins; ++i) {
    const std::uint32_t count = s.histogram[static_cast<std::size_t>(i)];
    if (count == 0) continue;
    std::cerr << "  " << (i == LoopStats::kBins - 1 ? ">=" : "") << i << " us: " << count << "\n";
  }
}

void BM_PacedHapticRun(benchmark::State& state) {
  const Scene scene = LoadScene(
      "cantilever-haptic",
      {SceneOverride::Parse("analysis.duration=10"), SceneOverride::Parse("device.realtime=true")});
  for (auto _ : state) {
    HapticSession session(scene, OpenDevice(scene));
    session.Start();
    session.opened().scripted->WaitUntilDone();
    session.Stop();
    const LoopStats servo = session.device().stats();
    const LoopStats& physics = session.loop().physics_stats();
    state.counters["ticks"] = static_cast<double>(servo.ticks);
    state.counters["rate_hz"] = servo.rate_hz;
    state.counters["realtime"] = servo.realtime ? 1 : 0;
    state.counters["deadline_misses"] = static_cast<double>(servo.deadline_misses);
    state.counters["period_max_us"] = servo.period_max_us;
    state.counters["tick_median_us"] = servo.ComputeQuantileUs(0.5);
    state.counters["tick_p99_us"] = servo.ComputeQuantileUs(0.99);
    state.counters["tick_max_us"] = servo.compute_max_us;
    state.counters["physics_median_us"] = physics.ComputeQuantileUs(0.5);
    state.counters["physics_p99_us"] = physics.ComputeQuantileUs(0.99);
    state.counters["physics_max_us"] = physics.compute_max_us;
    state.counters["physics_misses"] = static_cast<double>(physics.deadline_misses);
    state.counters["failed_physics"] = static_cast<double>(session.loop().failed_ticks());
    PrintHistogram(servo, "servo tick");
    PrintHistogram(physics, "physics tick");
  }
}
BENCHMARK(BM_PacedHapticRun)->Iterations(1)->Unit(benchmark::kSecond);

void BM_BareTimer(benchmark::State& state) {
  for (auto _ : state) {
    LoopStats stats;
    std::thread thread([&stats] {
      const bool realtime = MakeThisThreadRealtime().fifo;
      LoopStatsRecorder recorder;
      recorder.Start(1e-3, true, realtime);
      PeriodicDeadline deadline(1000.0);
      for (int tick = 0; tick <= 10000; ++tick) {
        deadline.SleepUntilNext();
        recorder.Record(
            std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
                .count(),
            0.0);
      }
      stats = recorder.stats();
    });
    thread.join();
    state.counters["rate_hz"] = stats.rate_hz;
    state.counters["realtime"] = stats.realtime ? 1 : 0;
    state.counters["deadline_misses"] = static_cast<double>(stats.deadline_misses);
    state.counters["period_max_us"] = stats.period_max_us;
  }
}
BENCHMARK(BM_BareTimer)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace cosmems
