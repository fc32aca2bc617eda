#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cosmems::internal {

/// The outputs a sweep summarises in one scene result: every top-level number (a boolean as 0
/// or 1: the mean of `stuck` is the fraction stuck) and each element of `frequencies_hz`, as
/// `frequencies_hz[0]`, ..., in the result's order.
std::vector<std::pair<std::string, double>> NumericOutputs(const nlohmann::ordered_json& result);

/// One output of a result by its field name (`name` or `name[i]`, as NumericOutputs names
/// them); nothing when the result lacks it or it is not a number.
std::optional<double> OutputValue(const nlohmann::ordered_json& result, const std::string& field);

}  // namespace cosmems::internal
