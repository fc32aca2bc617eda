#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace cosmems {

/// Figures of a servo loop: rate, tick compute time and lateness.
struct LoopStats {
  /// Compute-time histogram: 1 us bins over [0, 2 ms); the last bin holds everything longer.
  static constexpr int kBins = 2001;
  static constexpr double kBinUs = 1.0;

  std::uint64_t ticks = 0;
  double rate_hz = 0.0;               ///< ticks per second of wall time since the start
  double period_max_us = 0.0;         ///< longest wall-clock interval between two ticks
  double compute_max_us = 0.0;        ///< longest tick (client + safety layer)
  std::uint64_t overruns = 0;         ///< ticks whose compute time exceeded the period
  std::uint64_t deadline_misses = 0;  ///< paced loops: an interval above 1.5 periods
  bool paced = false;                 ///< ticks follow the wall clock (else: as fast as possible)
  bool realtime = false;              ///< the servo thread runs SCHED_FIFO with locked memory
  std::array<std::uint32_t, kBins> histogram{};

  /// The compute time below which a fraction q of the ticks fall [us], to the bin width (the
  /// bin's upper edge, so never optimistic); the largest time itself for q = 1.
  double ComputeQuantileUs(double q) const {
    if (ticks == 0) return 0.0;
    if (q >= 1.0) return compute_max_us;
    const double wanted = q * static_cast<double>(ticks);
    double seen = 0.0;
    for (int i = 0; i < kBins; ++i) {
      seen += histogram[static_cast<std::size_t>(i)];
      if (seen >= wanted) return std::min((i + 1) * kBinUs, compute_max_us);
    }
    return compute_max_us;
  }
};

/// Fills LoopStats from the servo thread, one Record() a tick; allocation-free.
class LoopStatsRecorder {
 public:
  void Start(double period_s, bool paced, bool realtime) {
    stats_ = LoopStats{};
    stats_.paced = paced;
    stats_.realtime = realtime;
    period_us_ = period_s * 1e6;
  }

  /// A backend knows whether its thread is real-time only once it runs.
  void MarkRealtime(bool realtime) { stats_.realtime = realtime; }

  /// One tick that began at `tick_start_s` (wall clock) and took `compute_us`.
  void Record(double tick_start_s, double compute_us) {
    const double interval_us = (tick_start_s - last_tick_s_) * 1e6;
    if (stats_.ticks == 0) {
      first_tick_s_ = tick_start_s;
    } else {
      stats_.period_max_us = std::max(stats_.period_max_us, interval_us);
      if (stats_.paced && interval_us > 1.5 * period_us_) ++stats_.deadline_misses;
    }
    last_tick_s_ = tick_start_s;
    ++stats_.ticks;
    stats_.compute_max_us = std::max(stats_.compute_max_us, compute_us);
    if (compute_us > period_us_) ++stats_.overruns;
    const int bin =
        std::min(LoopStats::kBins - 1, static_cast<int>(compute_us / LoopStats::kBinUs));
    ++stats_.histogram[static_cast<std::size_t>(std::max(bin, 0))];
    // Rate over the intervals between the first and the latest tick.
    const double elapsed_s = tick_start_s - first_tick_s_;
    if (elapsed_s > 0.0) stats_.rate_hz = static_cast<double>(stats_.ticks - 1) / elapsed_s;
  }

  const LoopStats& stats() const { return stats_; }

 private:
  LoopStats stats_;
  double period_us_ = 1000.0;
  double first_tick_s_ = 0.0;
  double last_tick_s_ = 0.0;
};

}  // namespace cosmems
