#include "toml_field_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "cosmems/scene/scene_error.hpp"
#include "toml_format.hpp"

namespace cosmems::internal {
namespace {

std::string JoinKey(const std::string& table, std::string_view key) {
  return table.empty() ? FormatKey(key) : table + "." + FormatKey(key);
}

std::string PlainList(const std::vector<std::string_view>& names) {
  std::string out;
  std::size_t i = 0;
  for (const std::string_view name : names) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += name;
    ++i;
  }
  return out;
}

// A TOML integer or float as a double. toml++'s value<double>() refuses integers that a double
// cannot hold exactly; a scene value that large is rounded like any other number.
double NumberValue(const toml::node& node) {
  if (node.is_integer()) return static_cast<double>(*node.value<std::int64_t>());
  return *node.value<double>();
}

}  // namespace

const toml::node* TomlFieldReader::Find(const std::string& key) const {
  return root_.at_path(key).node();
}

void TomlFieldReader::Fail(const std::string& key, const std::string& reason) const {
  const toml::node* node = Find(key);
  throw SceneError(origins_.SourceOf(key), key, node ? FormatToml(*node) : "", reason);
}

void TomlFieldReader::Fail(const std::string& key, const toml::node& value,
                           const std::string& reason) const {
  throw SceneError(origins_.SourceOf(key), key, FormatToml(value), reason);
}

void TomlFieldReader::FailWithoutValue(const std::string& key, const std::string& reason) const {
  throw SceneError(origins_.SourceOf(key), key, "", reason);
}

void TomlFieldReader::FailMissing(const std::string& key) const {
  throw SceneError(origins_.SourceOf(key), key, "", "missing required key");
}

std::string TomlFieldReader::QuotedList(const std::vector<std::string_view>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
    out += "\"" + std::string(names[i]) + "\"";
  }
  return out;
}

void TomlFieldReader::RejectUnknownKeys(const std::string& table,
                                        const std::vector<std::string_view>& known,
                                        const std::vector<std::string_view>& listed,
                                        std::string_view noun) const {
  const toml::table& entries = table.empty() ? root_ : *Find(table)->as_table();
  for (const auto& [key, value] : entries) {
    if (std::find(known.begin(), known.end(), key.str()) == known.end()) {
      Fail(JoinKey(table, key.str()), value,
           "unknown " + std::string(noun) + " (expected " + PlainList(listed) + ")");
    }
  }
}

std::vector<std::string> TomlFieldReader::Keys(const std::string& table) const {
  std::vector<std::string> keys;
  for (const auto& [key, value] : *Find(table)->as_table()) keys.emplace_back(key.str());
  return keys;
}

bool TomlFieldReader::HasTable(const std::string& key) const {
  const toml::node* node = Find(key);
  if (node == nullptr) return false;
  Require(node->is_table(), key, "expected a table");
  return true;
}

void TomlFieldReader::RequireTable(const std::string& key) const {
  if (!HasTable(key)) throw SceneError(origins_.SourceOf(key), key, "", "missing required table");
}

std::optional<double> TomlFieldReader::OptionalNumber(const std::string& key) const {
  const toml::node* node = Find(key);
  if (node == nullptr) return std::nullopt;
  Require(node->is_number(), key, "expected a number");
  const double value = NumberValue(*node);
  Require(std::isfinite(value), key, "must be finite");
  return value;
}

double TomlFieldReader::RequiredNumber(const std::string& key) const {
  const std::optional<double> value = OptionalNumber(key);
  if (!value) FailMissing(key);
  return *value;
}

double TomlFieldReader::Number(const std::string& key, double fallback) const {
  return OptionalNumber(key).value_or(fallback);
}

double TomlFieldReader::RequiredPositive(const std::string& key) const {
  const double value = RequiredNumber(key);
  Require(value > 0.0, key, "must be positive");
  return value;
}

std::optional<double> TomlFieldReader::OptionalPositive(const std::string& key) const {
  const std::optional<double> value = OptionalNumber(key);
  if (value) Require(*value > 0.0, key, "must be positive");
  return value;
}

std::optional<double> TomlFieldReader::OptionalNonNegative(const std::string& key) const {
  const std::optional<double> value = OptionalNumber(key);
  if (value) Require(*value >= 0.0, key, "must be non-negative");
  return value;
}

void TomlFieldReader::RequireWithin(const std::string& key, double value,
                                    const Bounds& bounds) const {
  const std::string unit = *bounds.unit != '\0' ? std::string(" ") + bounds.unit : "";
  Require(value >= bounds.lower && value <= bounds.upper, key,
          "must lie in [" + FormatNumber(bounds.lower) + ", " + FormatNumber(bounds.upper) + "]" +
              unit);
}

std::optional<double> TomlFieldReader::OptionalNumber(const std::string& key,
                                                      const Bounds& bounds) const {
  const std::optional<double> value = OptionalNumber(key);
  if (value) RequireWithin(key, *value, bounds);
  return value;
}

double TomlFieldReader::RequiredPositive(const std::string& key, const Bounds& bounds) const {
  const double value = RequiredPositive(key);
  RequireWithin(key, value, bounds);
  return value;
}

std::optional<double> TomlFieldReader::OptionalPositive(const std::string& key,
                                                        const Bounds& bounds) const {
  const std::optional<double> value = OptionalPositive(key);
  if (value) RequireWithin(key, *value, bounds);
  return value;
}

std::optional<double> TomlFieldReader::OptionalNonNegative(const std::string& key,
                                                           const Bounds& bounds) const {
  const std::optional<double> value = OptionalNonNegative(key);
  if (value) RequireWithin(key, *value, bounds);
  return value;
}

int TomlFieldReader::Integer(const std::string& key, int fallback) const {
  const toml::node* node = Find(key);
  if (node == nullptr) return fallback;
  Require(node->is_integer(), key, "expected an integer");
  const std::int64_t value = *node->value<std::int64_t>();
  Require(value >= std::numeric_limits<int>::min() && value <= std::numeric_limits<int>::max(), key,
          "out of range");
  return static_cast<int>(value);
}

bool TomlFieldReader::Boolean(const std::string& key, bool fallback) const {
  const toml::node* node = Find(key);
  if (node == nullptr) return fallback;
  Require(node->is_boolean(), key, "expected a boolean (true or false)");
  return *node->value<bool>();
}

std::optional<std::string> TomlFieldReader::OptionalString(const std::string& key) const {
  const toml::node* node = Find(key);
  if (node == nullptr) return std::nullopt;
  Require(node->is_string(), key, "expected a string");
  return *node->value<std::string>();
}

std::optional<std::vector<double>> TomlFieldReader::OptionalNumbers(const std::string& key,
                                                                    std::size_t count) const {
  const toml::node* node = Find(key);
  if (node == nullptr) return std::nullopt;
  const std::string expected = "expected an array of " + std::to_string(count) + " numbers";
  const toml::array* array = node->as_array();
  Require(array != nullptr && array->size() == count, key, expected);
  std::vector<double> values;
  for (std::size_t i = 0; i < count; ++i) {
    const toml::node& element = (*array)[i];
    Require(element.is_number(), key, expected);
    values.push_back(NumberValue(element));
    const std::string element_key = key + "[" + std::to_string(i) + "]";
    Require(std::isfinite(values.back()), element_key, "must be finite");
  }
  return values;
}

}  // namespace cosmems::internal
