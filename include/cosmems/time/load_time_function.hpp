#pragma once

#include <cmath>

#include "cosmems/core/constants.hpp"

namespace cosmems {

/// How a load pattern varies in time, as an amplitude s(t) that multiplies it.
struct LoadTimeFunction {
  enum class Kind {
    kStep,  ///< s = 1 from t = 0 on (suddenly applied)
    kRamp,  ///< s = t / ramp_time up to ramp_time, then 1
    kSine,  ///< s = sin(2 pi frequency t)
    kZero,  ///< s = 0: the loads are removed at t = 0 (release from a static state)
  };
  Kind kind = Kind::kStep;
  double ramp_time = 0.0;  ///< s
  double frequency = 0.0;  ///< Hz

  double Value(double t) const {
    switch (kind) {
      case Kind::kStep:
        return 1.0;
      case Kind::kRamp:
        return t >= ramp_time ? 1.0 : t / ramp_time;
      case Kind::kSine:
        return std::sin(2.0 * kPi * frequency * t);
      case Kind::kZero:
        break;
    }
    return 0.0;
  }
};

}  // namespace cosmems
