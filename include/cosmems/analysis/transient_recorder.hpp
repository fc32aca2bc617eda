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

/// The stepping loop every transient run shares, whatever its model: it times each step, keeps
/// an evenly strided history of uy at the output point and its extremes, stops at the first
/// failed step with its status, and declares a run diverged when uy leaves a thousand beam
/// lengths (an explicit step just above its stability limit grows geometrically long before it
/// overflows).
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
    step_us_.reserve(static_cast<std::size_t>(steps_));
  }

  long steps() const { return steps_; }

  /// Runs the steps into `result`: `step(i)` advances to step i and returns its status,
  /// `sample()` returns uy [m] at the output point.
  template <typename Step, typename Sample>
  void Run(TransientResult& result, Step&& step, Sample&& sample) {
    Record(result, 0, sample());
    for (long i = 1; i <= steps_; ++i) {
      const auto before = Clock::now();
      const Status status = step(i);
      step_us_.push_back(std::chrono::duration<double, std::micro>(Clock::now() - before).count());
      if (status != Status::kOk) {
        result.status = status;
        return;
      }
      result.steps = i;
      const double uy = sample();
      Record(result, i, uy);
      if (std::abs(uy) > divergence_) {
        result.status = Status::kDiverged;
        return;
      }
    }
  }

  /// Sets the timing figures of `result` once the run is over.
  void Finish(TransientResult& result) {
    for (const double us : step_us_) result.stepping_time_s += 1e-6 * us;
    result.step_time = StepTiming::From(std::move(step_us_));
    result.simulated_time_s = static_cast<double>(result.steps) * time_step_;
    result.wall_time_s = std::chrono::duration<double>(Clock::now() - start_).count();
  }

 private:
  void Record(TransientResult& result, long i, double uy) const {
    result.max_abs_output = std::max(result.max_abs_output, std::abs(uy));
    result.max_toward_substrate = std::max(result.max_toward_substrate, -uy);
    if (i % stride_ == 0 || i == steps_) {
      result.time_s.push_back(static_cast<double>(i) * time_step_);
      result.output_m.push_back(uy);
    }
  }

  double time_step_;
  long steps_;
  long stride_;
  double divergence_;
  Clock::time_point start_;
  std::vector<double> step_us_;
};

}  // namespace cosmems
