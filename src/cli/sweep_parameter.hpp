#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cosmems::internal {

/// One scene key a sweep varies and how its values are chosen (doc/sweeps.md): a grid of values
/// (`A:B:N`, `log:A:B:N`, a TOML list) or a distribution that the sweep's method draws from
/// (`uniform:A:B`, `normal:MEAN:SIGMA`, `lognormal:MEAN:SIGMA` of the value itself,
/// `truncnormal:MEAN:SIGMA:LO:HI`).
class SweepParameter {
 public:
  enum class Kind { kGrid, kUniform, kNormal, kLogNormal, kTruncatedNormal };

  /// Throws CliInputError naming the key and the spec when the spec is malformed or its numbers
  /// are out of range (a sigma that is not positive, log bounds that are not, LO >= HI, ...).
  SweepParameter(std::string key, std::string spec);

  const std::string& key() const { return key_; }
  const std::string& spec() const { return spec_; }
  Kind kind() const { return kind_; }
  bool IsGrid() const { return kind_ == Kind::kGrid; }
  /// A grid's values: numbers, strings or booleans, as JSON.
  const std::vector<nlohmann::json>& values() const { return values_; }
  /// A random parameter's value at the probability u in (0, 1) of its distribution.
  double Quantile(double u) const;
  /// A value the scene must accept for the sweep to make sense: a grid's first, a
  /// distribution's median.
  nlohmann::json Nominal() const;

 private:
  std::string key_;
  std::string spec_;
  Kind kind_ = Kind::kGrid;
  std::vector<nlohmann::json> values_;
  double mean_ = 0.0, sigma_ = 0.0;  ///< of the normal (of the log for the log-normal)
  double low_ = 0.0, high_ = 0.0;    ///< uniform's bounds; truncated normal's, as probabilities
};

/// A value as the TOML literal a `--set` reads: integers and booleans as written, a float with
/// the fewest digits that read back to it, a string quoted.
std::string TomlLiteral(const nlohmann::json& value);

}  // namespace cosmems::internal
