#pragma once

#include <stdexcept>
#include <string>

#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/load_time_function.hpp"
#include "cosmems/time/stepper_options.hpp"

namespace cosmems {

struct TransientOptions {
  double duration = 0.0;   ///< s
  double time_step = 0.0;  ///< s
  TimePath path = TimePath::kNewmarkFamily;
  GeneralizedAlphaParameters parameters;  ///< for kNewmarkFamily
  int modes = 0;                          ///< for kModal: >= 1
  /// false: from rest, loads applied by `time_function`; true: from the static deflection under
  /// the loads, which are removed at t = 0 (a release).
  bool start_static = false;
  LoadTimeFunction time_function;
  DampingModel damping;
  SpdSolverKind solver = SpdSolverKind::kAuto;
  double output_x = 0.0;    ///< m: where uy is recorded (the tip or mid-span)
  int max_history = 20000;  ///< samples kept in the history, evenly strided

  /// The stepper's share of these options.
  StepperOptions Stepper() const {
    StepperOptions out;
    out.path = path;
    out.time_step = time_step;
    out.parameters = parameters;
    out.modes = modes;
    out.damping = damping;
    out.solver = solver;
    return out;
  }

  /// The load amplitude at step `i`: the time function's, or 0 after a static start.
  double Amplitude(long i) const {
    return start_static ? 0.0 : time_function.Value(static_cast<double>(i) * time_step);
  }

  void Validate() const {
    RequirePositive("analysis.duration", duration);
    RequirePositive("analysis.time_step", time_step);
    if (time_step > duration) {
      throw std::invalid_argument("analysis.time_step = " + FormatValue(time_step) +
                                  ": longer than analysis.duration = " + FormatValue(duration));
    }
    if (path == TimePath::kModal && modes < 1) {
      throw std::invalid_argument("model.modes = " + std::to_string(modes) +
                                  ": the modal integrator needs at least one mode");
    }
  }
};

}  // namespace cosmems
