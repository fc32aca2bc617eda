#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <vector>

#include "cosmems/analysis/step_timing.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/analysis/transient_result.hpp"

namespace cosmems {

/// The stepping loop every transient run shares, whatever its model: it times the steps, keeps
/// an evenly strided history of uy at the output point and its extremes, stops at the first
/// failed step with its status, and declares a run diverged when uy leaves a thousand beam
/// lengths (an explicit step just above its stability limit grows geometrically long before it
/// overflows).
///
/// Steps are timed in batches. A clock read costs tens of nanoseconds here, as much as a modal
/// step: read around every step it took half of a four-mode run's time. The first kProbe steps
/// are timed one by one; from their median and the clock's own cost, a batch is then the fewest
/// steps that take at least kClockReads clock reads' time (the two reads per batch cost 2 % by
/// that count; in the run, where a read costs more than back to back, 20 reads' batches still
/// spent a tenth of a four-mode run in the clock), one step when a step costs more than that
/// (every Newton step), at most kMaxBatch.
/// A batch's figure is its time per step, its output read included: what a caller stepping the
/// model sees per step, averaged over the batch (StepTiming::batch says over how many).
class TransientRecorder {
 public:
  using Clock = std::chrono::steady_clock;

  /// `length` is the beam's [m]; the run's clock starts here, so set-up done after it counts in
  /// the wall time.
  TransientRecorder(const TransientOptions& options, double length)
      : time_step_(options.time_step),
        steps_(std::llround(options.duration / options.time_step)),
        stride_(std::max<long>(1, steps_ / std::max(1, options.max_history))),
        divergence_(1e3 * length),
        start_(Clock::now()) {
    step_us_.reserve(static_cast<std::size_t>(std::min<long>(steps_, kProbe)));
  }

  long steps() const { return steps_; }

  /// Runs the steps into `result`: `step(i)` advances to step i and returns its status,
  /// `sample()` returns uy [m] at the output point.
  template <typename Step, typename Sample>
  void Run(TransientResult& result, Step&& step, Sample&& sample) {
    Run(result, step, sample, [] {});
  }

  /// The same, calling `keep()` at every sample the history keeps (after its time is kept), for
  /// a caller that records more than the output point there.
  template <typename Step, typename Sample, typename Keep>
  void Run(TransientResult& result, Step&& step, Sample&& sample, Keep&& keep) {
    if (Record(result, 0, sample())) keep();
    long batch = 1;
    for (long i = 1; i <= steps_;) {
      if (i == kProbe + 1) batch = Batch();
      const long last = std::min(steps_, i + batch - 1), first = i;
      Status status = Status::kOk;
      const auto before = Clock::now();
      for (; i <= last; ++i) {
        status = step(i);
        if (status != Status::kOk) break;
        result.steps = i;
        const double uy = sample();
        if (Record(result, i, uy)) keep();
        if (std::abs(uy) > divergence_) {
          status = Status::kDiverged;
          break;
        }
      }
      const double us = std::chrono::duration<double, std::micro>(Clock::now() - before).count();
      const long timed = std::min(i, last) - first + 1;
      step_us_.push_back(us / static_cast<double>(timed));
      stepping_us_ += us;
      batch_ = batch;
      if (status != Status::kOk) {
        result.status = status;
        return;
      }
    }
  }

  /// Sets the timing figures of `result` once the run is over.
  void Finish(TransientResult& result) {
    result.stepping_time_s = 1e-6 * stepping_us_;
    result.step_time = StepTiming::From(std::move(step_us_));
    result.step_time.batch = batch_;
    result.simulated_time_s = static_cast<double>(result.steps) * time_step_;
    result.wall_time_s = std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  static constexpr long kProbe = 32;
  static constexpr double kClockReads = 100.0;
  static constexpr long kMaxBatch = 4096;

  // The batch for the rest of the run, from the probe's steps; reserves the figures' room.
  long Batch() {
    std::vector<double> probe = step_us_;
    std::nth_element(probe.begin(), probe.begin() + kProbe / 2, probe.end());
    const double median = probe[kProbe / 2];
    const double wanted = kClockReads * ClockReadUs();
    const long batch =
        median >= wanted ? 1 : std::min<long>(kMaxBatch, std::lround(std::ceil(wanted / median)));
    step_us_.reserve(static_cast<std::size_t>(kProbe + (steps_ - kProbe) / batch + 1));
    return batch;
  }

  // The cost of one clock read [us], the least of a few runs of back-to-back reads.
  static double ClockReadUs() {
    constexpr int kReads = 64;
    double best = 1e9;
    for (int run = 0; run < 4; ++run) {
      const auto start = Clock::now();
      Clock::time_point last = start;
      for (int k = 0; k < kReads; ++k) last = Clock::now();
      best = std::min(best, std::chrono::duration<double, std::micro>(last - start).count());
    }
    return best / kReads;
  }

  // Whether the sample is kept in the history.
  bool Record(TransientResult& result, long i, double uy) {
    result.max_abs_output = std::max(result.max_abs_output, std::abs(uy));
    result.max_toward_substrate = std::max(result.max_toward_substrate, -uy);
    // A countdown, not i % stride: a division per step costs as much as a modal step.
    if (--until_kept_ <= 0 || i == steps_) {
      result.time_s.push_back(static_cast<double>(i) * time_step_);
      result.output_m.push_back(uy);
      until_kept_ = stride_;
      return true;
    }
    return false;
  }

  double time_step_;
  long steps_;
  long stride_;
  long until_kept_ = 1;  ///< steps until the next kept sample (the first: step 0)
  double divergence_;
  Clock::time_point start_;
  std::vector<double> step_us_;  ///< per batch: its time per step
  double stepping_us_ = 0.0;
  long batch_ = 1;
};

}  // namespace cosmems
