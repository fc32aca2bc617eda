#pragma once

#include <algorithm>
#include <vector>

namespace cosmems {

/// Median, 99th percentile and maximum of per-step compute times [us], each sample the time per
/// step of `batch` steps timed together (1: every step timed alone).
struct StepTiming {
  double median_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
  long batch = 1;

  static StepTiming From(std::vector<double> samples_us) {
    StepTiming t;
    if (samples_us.empty()) return t;
    auto at = [&](double q) {
      const auto k = static_cast<std::size_t>(q * static_cast<double>(samples_us.size() - 1));
      std::nth_element(samples_us.begin(), samples_us.begin() + static_cast<long>(k),
                       samples_us.end());
      return samples_us[k];
    };
    t.median_us = at(0.5);
    t.p99_us = at(0.99);
    t.max_us = *std::max_element(samples_us.begin(), samples_us.end());
    return t;
  }
};

}  // namespace cosmems
