#pragma once

#include <time.h>

#include <cerrno>
#include <cmath>
#include <cstdint>

namespace cosmems {

/// Sleeps a thread from one tick deadline to the next on CLOCK_MONOTONIC: the pacing of the
/// scripted device's servo loop and of the haptic physics thread. Deadline n is anchor + n
/// periods, computed from the anchor rather than by adding periods, so rounding a period to
/// whole nanoseconds never accumulates into drift; the thread sleeps in
/// clock_nanosleep(TIMER_ABSTIME), never spinning (a spinning SCHED_FIFO thread is throttled by
/// the kernel for 50 ms every second). A late tick finds its next deadlines already past and
/// runs without sleeping until it has caught up, which keeps tick n near n periods of wall time.
class PeriodicDeadline {
 public:
  /// Anchors deadline 0 at the current time.
  explicit PeriodicDeadline(double rate_hz) : period_ns_(1e9 / rate_hz) {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    anchor_ns_ = static_cast<std::int64_t>(now.tv_sec) * kNsPerS + now.tv_nsec;
  }

  /// Sleeps until the next deadline (at once if it has passed).
  void SleepUntilNext() noexcept {
    ++next_;
    const std::int64_t deadline_ns =
        anchor_ns_ + std::llround(static_cast<double>(next_) * period_ns_);
    timespec deadline{};
    deadline.tv_sec = static_cast<time_t>(deadline_ns / kNsPerS);
    deadline.tv_nsec = static_cast<long>(deadline_ns % kNsPerS);
    // A signal interrupts the sleep; the deadline is absolute, so sleeping again loses nothing.
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &deadline, nullptr) == EINTR) {
    }
  }

 private:
  static constexpr std::int64_t kNsPerS = 1'000'000'000;
  std::int64_t anchor_ns_ = 0;
  double period_ns_ = 0.0;
  std::uint64_t next_ = 0;
};

}  // namespace cosmems
