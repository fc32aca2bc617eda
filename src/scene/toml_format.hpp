#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>

namespace cosmems::internal {

/// A TOML value spelled on one line the way a scene file would hold it, for error messages:
/// strings quoted and escaped, floats always with a '.', an exponent or inf/nan (20.0, not 20),
/// arrays as [a, b] and tables inline as { key = value }.
std::string FormatToml(const toml::node& node);

/// The shortest text that reads back as exactly `value`, fixed or scientific, whichever is
/// shorter: 20, 0.02, 2e-06, 1.69e+11.
std::string FormatNumber(double value);

/// A TOML float that reads back as exactly `value`: FormatNumber with a '.' where it would
/// otherwise read as an integer (20.0, not 20).
std::string FormatFloat(double value);

/// Whether `key` is a TOML bare key: [A-Za-z0-9_-]+.
bool IsBareKey(std::string_view key);

/// A key as TOML writes it: bare when it can be, quoted otherwise.
std::string FormatKey(std::string_view key);

}  // namespace cosmems::internal
