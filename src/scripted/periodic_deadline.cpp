#include "periodic_deadline.hpp"

#include <time.h>

#include <cerrno>
#include <cmath>

namespace cosmems {
namespace {

constexpr std::int64_t kNsPerS = 1'000'000'000;

}  // namespace

PeriodicDeadline::PeriodicDeadline(double rate_hz) : period_ns_(1e9 / rate_hz) {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  anchor_ns_ = static_cast<std::int64_t>(now.tv_sec) * kNsPerS + now.tv_nsec;
}

void PeriodicDeadline::SleepUntilNext() noexcept {
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

}  // namespace cosmems
