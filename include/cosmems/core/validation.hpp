#pragma once

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cosmems {

/// Formats a value the way error messages quote it: the fewest significant digits that read
/// back to the same double (17 always do).
inline std::string FormatValue(double value) {
  std::string text;
  for (int digits = 1; digits <= 17; ++digits) {
    std::ostringstream trial;
    trial.precision(digits);
    trial << value;
    text = trial.str();
    double back = 0.0;
    std::istringstream(text) >> back;
    if (back == value) break;
  }
  return text;
}

/// Invalid input found at a field a caller can point to (a scene names its value): what() is
/// "FIELD: REASON".
class FieldError : public std::invalid_argument {
 public:
  FieldError(const std::string& field, const std::string& reason)
      : std::invalid_argument(field + ": " + reason), field_(field), reason_(reason) {}
  const std::string& field() const { return field_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string field_;
  std::string reason_;
};

/// Throws std::invalid_argument("FIELD = VALUE: must be positive") unless 0 < value < inf.
inline void RequirePositive(const std::string& field, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(field + " = " + FormatValue(value) +
                                ": must be positive and finite");
  }
}

/// Throws std::invalid_argument unless lower < value < upper.
inline void RequireInRange(const std::string& field, double value, double lower, double upper) {
  if (!(value > lower && value < upper)) {
    throw std::invalid_argument(field + " = " + FormatValue(value) + ": must lie in (" +
                                FormatValue(lower) + ", " + FormatValue(upper) + ")");
  }
}

/// Throws std::invalid_argument unless lower <= value <= upper.
inline void RequireWithin(const std::string& field, double value, double lower, double upper) {
  if (!(value >= lower && value <= upper)) {
    throw std::invalid_argument(field + " = " + FormatValue(value) + ": must lie in [" +
                                FormatValue(lower) + ", " + FormatValue(upper) + "]");
  }
}

/// Throws std::invalid_argument unless value is finite.
inline void RequireFinite(const std::string& field, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(field + " = " + FormatValue(value) + ": must be finite");
  }
}

/// Throws std::invalid_argument("FIELD has SIZE entries: must have EXPECTED (WHAT)") unless
/// size == expected.
inline void RequireSize(const std::string& field, long size, long expected,
                        const std::string& what) {
  if (size != expected) {
    throw std::invalid_argument(field + " has " + std::to_string(size) + " entries: must have " +
                                std::to_string(expected) + " (" + what + ")");
  }
}

}  // namespace cosmems
