#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace cosmems::internal {

/// A condition on one output of a sample, `FIELD OP NUMBER` with OP one of >=, <=, >, <, ==,
/// != (`pullin_voltage_v>=20`, `frequencies_hz[0]<75000`, `stuck==0`): the yield of a sweep is
/// the fraction of its samples that meet all of them.
class SweepCondition {
 public:
  /// Throws CliInputError naming the text when it is not FIELD OP NUMBER.
  explicit SweepCondition(const std::string& text);

  const std::string& text() const { return text_; }
  const std::string& field() const { return field_; }
  double bound() const { return bound_; }
  /// False when the result lacks the field or it is not a number (a failed sample's).
  bool Met(const nlohmann::ordered_json& result) const;

 private:
  std::string text_;
  std::string field_;
  std::string op_;
  double bound_ = 0.0;
};

}  // namespace cosmems::internal
