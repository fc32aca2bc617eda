#pragma once

#include <toml++/toml.h>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "key_origins.hpp"

namespace cosmems::internal {

/// A closed range of accepted values and its unit as messages spell it ("" for none).
struct Bounds {
  double lower;
  double upper;
  const char* unit;
};

/// Typed access to a parsed scene by dotted key ("structure.length"). Every failure throws a
/// SceneError naming the key's origin, the key and its value.
///
/// Numbers accept TOML integers and floats and must be finite; integers must be TOML integers
/// (20, not 20.0) within the range of int.
class TomlFieldReader {
 public:
  TomlFieldReader(const toml::table& root, const KeyOrigins& origins)
      : root_(root), origins_(origins) {}

  /// The node at `key`, or nullptr.
  const toml::node* Find(const std::string& key) const;

  /// Throws "SOURCE: KEY = VALUE: REASON" with the value found at `key`.
  [[noreturn]] void Fail(const std::string& key, const std::string& reason) const;
  /// The same with the value given.
  [[noreturn]] void Fail(const std::string& key, const toml::node& value,
                         const std::string& reason) const;
  /// Throws "SOURCE: KEY: REASON", leaving out the value: for a key that holds a whole netlist.
  [[noreturn]] void FailWithoutValue(const std::string& key, const std::string& reason) const;
  /// Throws Fail(key, reason) unless `condition`.
  void Require(bool condition, const std::string& key, const std::string& reason) const {
    if (!condition) Fail(key, reason);
  }

  /// Throws "unknown NOUN (expected ...)" for the first key of `table` ("" is the root) that is
  /// not in `known`.
  void RejectUnknownKeys(const std::string& table, const std::vector<std::string_view>& known,
                         std::string_view noun = "key") const {
    RejectUnknownKeys(table, known, known, noun);
  }
  /// The same, the message listing only `listed` (the keys the scene's choices read).
  void RejectUnknownKeys(const std::string& table, const std::vector<std::string_view>& known,
                         const std::vector<std::string_view>& listed,
                         std::string_view noun = "key") const;

  /// The keys of the table at `table`, in the file's order.
  std::vector<std::string> Keys(const std::string& table) const;

  /// Whether `key` holds a table; throws when it holds anything else.
  bool HasTable(const std::string& key) const;
  /// Throws "missing required table" unless `key` holds a table.
  void RequireTable(const std::string& key) const;

  std::optional<double> OptionalNumber(const std::string& key) const;
  double RequiredNumber(const std::string& key) const;
  double Number(const std::string& key, double fallback) const;
  /// A required number > 0.
  double RequiredPositive(const std::string& key) const;
  /// An optional number > 0.
  std::optional<double> OptionalPositive(const std::string& key) const;
  /// An optional number >= 0.
  std::optional<double> OptionalNonNegative(const std::string& key) const;

  /// Throws "must lie in [LOWER, UPPER] UNIT" unless `value`, read at `key`, is within `bounds`.
  void RequireWithin(const std::string& key, double value, const Bounds& bounds) const;
  /// The readers above, then RequireWithin.
  std::optional<double> OptionalNumber(const std::string& key, const Bounds& bounds) const;
  double RequiredPositive(const std::string& key, const Bounds& bounds) const;
  std::optional<double> OptionalPositive(const std::string& key, const Bounds& bounds) const;
  std::optional<double> OptionalNonNegative(const std::string& key, const Bounds& bounds) const;

  int Integer(const std::string& key, int fallback) const;
  bool Boolean(const std::string& key, bool fallback) const;
  std::optional<std::string> OptionalString(const std::string& key) const;

  /// An array of exactly `count` numbers.
  std::optional<std::vector<double>> OptionalNumbers(const std::string& key,
                                                     std::size_t count) const;

  /// A string naming one of `options` (as ToString spells them); empty when absent.
  template <class Enum, std::size_t N>
  std::optional<Enum> OptionalChoice(const std::string& key, const std::array<Enum, N>& options,
                                     std::string_view what) const {
    const std::optional<std::string> name = OptionalString(key);
    if (!name) return std::nullopt;
    std::vector<std::string_view> names;
    for (const Enum option : options) {
      if (*name == ToString(option)) return option;
      names.emplace_back(ToString(option));
    }
    Fail(key, "unknown " + std::string(what) + " (expected " + QuotedList(names) + ")");
  }

  template <class Enum, std::size_t N>
  Enum RequiredChoice(const std::string& key, const std::array<Enum, N>& options,
                      std::string_view what) const {
    const std::optional<Enum> choice = OptionalChoice(key, options, what);
    if (!choice) FailMissing(key);
    return *choice;
  }

  /// Throws "KEY: missing required key".
  [[noreturn]] void FailMissing(const std::string& key) const;

 private:
  /// "\"a\", \"b\" or \"c\"".
  static std::string QuotedList(const std::vector<std::string_view>& names);

  const toml::table& root_;
  const KeyOrigins& origins_;
};

}  // namespace cosmems::internal
