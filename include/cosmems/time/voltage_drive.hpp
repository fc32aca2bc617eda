#pragma once

#include <cmath>

#include "cosmems/core/constants.hpp"

namespace cosmems {

/// A transducer's voltage in time, V(t) = dc + ac sin(2 pi f t). Its force goes with V^2: a mean
/// dc^2 + ac^2 / 2, a push at f of amplitude 2 dc ac (what drives a resonator at its frequency)
/// and one at 2 f of amplitude ac^2 / 2.
struct VoltageDrive {
  double dc = 0.0;            ///< V
  double ac = 0.0;            ///< V, the amplitude of the alternating part
  double frequency_hz = 0.0;  ///< of the alternating part

  double At(double t_s) const { return dc + ac * std::sin(2.0 * kPi * frequency_hz * t_s); }
  double SquaredAt(double t_s) const {
    const double v = At(t_s);
    return v * v;
  }
};

}  // namespace cosmems
