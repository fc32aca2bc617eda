#pragma once

namespace cosmems {

/// pi, spelled out because M_PI is not standard C++.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace cosmems
