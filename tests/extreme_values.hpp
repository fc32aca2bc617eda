#pragma once

// Values that break naive arithmetic on a force, a position or a velocity: finite magnitudes
// whose square or product with a rate overflows (1e150 and up to the largest double) and
// denormals, whose square underflows to zero. Both signs.
#include <limits>
#include <vector>

namespace cosmems::test {

inline std::vector<double> ExtremeValues() {
  const double largest = std::numeric_limits<double>::max();
  const double smallest = std::numeric_limits<double>::denorm_min();
  std::vector<double> values;
  for (const double m : {1e150, 1e154, 1e155, 1e200, 1e300, 1e307, 1e308, largest, smallest, 1e-310,
                         1e-320, 1e-160}) {
    values.push_back(m);
    values.push_back(-m);
  }
  return values;
}

}  // namespace cosmems::test
