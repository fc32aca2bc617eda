#pragma once

#include <Eigen/Core>
#include <string>

namespace cosmems::internal {

// Numbers for the readable summary: a few significant digits, as an engineer reads them.

/// Scientific notation with `digits` significant digits ("-1.1834e-07"); "0" for zero.
std::string Scientific(double value, int digits = 5);

/// The shortest of fixed and scientific notation with `digits` significant digits ("42.123").
std::string Significant(double value, int digits = 5);

/// "[x, y, z]" in Scientific().
std::string Vector(const Eigen::Vector3d& value);

}  // namespace cosmems::internal
