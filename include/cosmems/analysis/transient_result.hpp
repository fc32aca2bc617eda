#pragma once

#include <vector>

#include "cosmems/analysis/step_timing.hpp"
#include "cosmems/core/status.hpp"

namespace cosmems {

/// What a transient run reports: its status, the steps it took and their timing, and the
/// history of uy at its output point.
struct TransientResult {
  Status status = Status::kOk;
  long steps = 0;
  StepTiming step_time;
  double wall_time_s = 0.0;      ///< set-up and stepping
  double stepping_time_s = 0.0;  ///< the steps alone (their timed sum)
  double simulated_time_s = 0.0;
  double max_abs_output = 0.0;  ///< m: largest |uy| at the output point
  /// m: largest -uy at the output point, its deflection toward the substrate (0 when it never
  /// moves that way)
  double max_toward_substrate = 0.0;
  std::vector<double> time_s;  ///< history
  std::vector<double> output_m;

  double RealtimeFactor() const { return wall_time_s > 0.0 ? simulated_time_s / wall_time_s : 0.0; }
};

}  // namespace cosmems
