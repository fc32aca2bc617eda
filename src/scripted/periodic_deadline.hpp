#pragma once

#include <cstdint>

namespace cosmems {

/// Sleeps a thread from one tick deadline to the next on CLOCK_MONOTONIC. Deadline n is
/// anchor + n periods, computed from the anchor rather than by adding periods, so rounding a
/// period to whole nanoseconds never accumulates into drift; the thread sleeps in
/// clock_nanosleep(TIMER_ABSTIME), never spinning (a spinning SCHED_FIFO thread is throttled
/// by the kernel for 50 ms every second). A late tick finds its next deadlines already past and
/// runs without sleeping until it has caught up, which keeps tick n near n periods of wall time.
class PeriodicDeadline {
 public:
  /// Anchors deadline 0 at the current time.
  explicit PeriodicDeadline(double rate_hz);

  /// Sleeps until the next deadline (at once if it has passed).
  void SleepUntilNext() noexcept;

 private:
  std::int64_t anchor_ns_ = 0;
  double period_ns_ = 0.0;
  std::uint64_t next_ = 0;
};

}  // namespace cosmems
