#pragma once

#include <time.h>

#include <cerrno>
#include <cmath>
#include <cstdint>

namespace cosmems {

/// What a PeriodicDeadline does after a tick that ran late past later deadlines.
enum class CatchUp {
  kAll,   ///< runs the missed ticks without sleeping: tick n stays near n periods of wall time
  kSkip,  ///< drops the missed deadlines and goes on from the next one still ahead
};

/// Sleeps a thread from one tick deadline to the next on CLOCK_MONOTONIC: the pacing of the
/// scripted device's servo loop and of the haptic physics thread. Deadline n is anchor + n
/// periods, computed from the anchor rather than by adding periods, so rounding a period to
/// whole nanoseconds never accumulates into drift; the thread sleeps in
/// clock_nanosleep(TIMER_ABSTIME), never spinning (a spinning SCHED_FIFO thread is throttled by
/// the kernel for 50 ms every second). A late tick finds its next deadlines already past: with
/// CatchUp::kAll it runs without sleeping until it has caught up (a device clock's tick n near n
/// periods of wall time); with CatchUp::kSkip it skips them (a worker on the newest input, which
/// gains nothing from running the same input again).
class PeriodicDeadline {
 public:
  /// Anchors deadline 0 at the current time.
  explicit PeriodicDeadline(double rate_hz, CatchUp catch_up = CatchUp::kAll)
      : period_ns_(1e9 / rate_hz), catch_up_(catch_up) {
    anchor_ns_ = NowNs();
  }

  /// Deadlines dropped so far (CatchUp::kSkip).
  std::uint64_t skipped() const { return skipped_; }

  /// Sleeps until the next deadline (at once if it has passed and CatchUp::kAll).
  void SleepUntilNext() noexcept {
    ++next_;
    if (catch_up_ == CatchUp::kSkip) {
      // The first deadline after now: the whole periods elapsed since the anchor, plus one.
      const auto ahead = static_cast<std::uint64_t>(
          std::floor(static_cast<double>(NowNs() - anchor_ns_) / period_ns_) + 1.0);
      if (ahead > next_) {
        skipped_ += ahead - next_;
        next_ = ahead;
      }
    }
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
  static std::int64_t NowNs() noexcept {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<std::int64_t>(now.tv_sec) * kNsPerS + now.tv_nsec;
  }
  std::int64_t anchor_ns_ = 0;
  double period_ns_ = 0.0;
  CatchUp catch_up_ = CatchUp::kAll;
  std::uint64_t next_ = 0;
  std::uint64_t skipped_ = 0;
};

}  // namespace cosmems
