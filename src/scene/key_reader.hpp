#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cosmems/structure/structure_description.hpp"
#include "scene_keys.hpp"
#include "toml_field_reader.hpp"
#include "toml_format.hpp"

namespace cosmems::internal {

/// Reads and validates the keys of one table as scene_keys.hpp describes them, into the fields
/// the visit names, and keeps their names. Every failure is a SceneError naming the key and its
/// value.
class KeyReader {
 public:
  /// `table`: the dotted table ("effects.contact"); `length`: the beam's, for Position keys.
  KeyReader(const TomlFieldReader& r, std::string table, double length = 0.0)
      : r_(r), table_(std::move(table)), length_(length) {}

  /// The keys the visit named, each once: those the table may hold.
  const std::vector<std::string_view>& names() const { return names_; }
  /// Those of them the scene's choices read (the others are refused when given).
  const std::vector<std::string_view>& chosen() const { return chosen_names_; }

  void Scope(const char* owner, bool chosen, Unchosen unchosen) {
    owner_ = owner;
    chosen_ = chosen;
    unchosen_ = unchosen;
  }

  void Required(const char* name, double& field, const NumberRule& rule, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    const std::optional<double> value = Read(key, rule);
    if (!value) r_.FailMissing(key);
    field = *value;
  }
  void Number(const char* name, double& field, const NumberRule& rule, const char*) {
    if (!Reads(name)) return;
    field = Read(Key(name), rule).value_or(field);
  }
  void Number(const char* name, std::optional<double>& field, const NumberRule& rule, const char*,
              const char*) {
    if (!Reads(name)) return;
    field = Read(Key(name), rule);
  }
  void Integer(const char* name, int& field, const IntegerRange& range, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    field = r_.Integer(key, field);
    if (range.upper == range.lower + 1) {
      r_.Require(field == range.lower || field == range.upper, key,
                 "must be " + std::to_string(range.lower) + " or " + std::to_string(range.upper));
    }
    r_.Require(field >= range.lower, key,
               range.lower == 0 ? "must be non-negative"
                                : "must be at least " + std::to_string(range.lower));
    r_.Require(field <= range.upper, key, "must be at most " + std::to_string(range.upper));
  }
  void Flag(const char* name, bool& field, const char*) {
    if (Reads(name)) field = r_.Boolean(Key(name), field);
  }
  template <class Enum, std::size_t N>
  void Choice(const char* name, Enum& field, const std::array<Enum, N>& options,
              std::string_view what, const char*) {
    if (Reads(name)) field = r_.OptionalChoice(Key(name), options, what).value_or(field);
  }
  template <class Enum, std::size_t N>
  void RequiredChoice(const char* name, Enum& field, const std::array<Enum, N>& options,
                      std::string_view what, const char*) {
    if (Reads(name)) field = r_.RequiredChoice(Key(name), options, what);
  }
  void Text(const char* name, std::string& field, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    field = r_.OptionalString(key).value_or(field);
    r_.Require(!field.empty(), key, "must not be empty");
  }
  void Vector(const char* name, Eigen::Vector3d& field, const Bounds& bounds, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    const std::optional<std::vector<double>> values = r_.OptionalNumbers(key, 3);
    if (!values) return;
    for (std::size_t i = 0; i < values->size(); ++i) {
      r_.RequireWithin(key + "[" + std::to_string(i) + "]", (*values)[i], bounds);
    }
    field = Eigen::Vector3d((*values)[0], (*values)[1], (*values)[2]);
  }
  void RequiredVector(const char* name, Eigen::Vector3d& field, const Bounds& bounds,
                      const char* meaning) {
    if (!Reads(name)) return;
    if (r_.Find(Key(name)) == nullptr) r_.FailMissing(Key(name));
    Vector(name, field, bounds, meaning);
  }
  void Integer(const char* name, std::optional<int>& field, const IntegerRange& range, const char*,
               const char* meaning) {
    if (!Reads(name) || r_.Find(Key(name)) == nullptr) return;
    int value = 0;
    Integer(name, value, range, meaning);
    field = value;
  }
  void RequiredText(const char* name, std::string& field, const char* meaning) {
    if (!Reads(name)) return;
    if (r_.Find(Key(name)) == nullptr) r_.FailMissing(Key(name));
    Text(name, field, meaning);
  }
  void OptionalText(const char* name, std::optional<std::string>& field, const char*,
                    const char* meaning) {
    if (!Reads(name) || r_.Find(Key(name)) == nullptr) return;
    std::string value;
    Text(name, value, meaning);
    field = value;
  }
  /// A required array of non-empty strings: exactly `count`, or one or more when count is 0.
  void Names(const char* name, std::vector<std::string>& field, std::size_t count, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    const toml::node* node = r_.Find(key);
    if (node == nullptr) r_.FailMissing(key);
    ReadNames(key, *node, count, field);
  }
  /// One or more names, or none when the key is absent.
  void OptionalNames(const char* name, std::vector<std::string>& field, const char*, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    if (const toml::node* node = r_.Find(key)) ReadNames(key, *node, 0, field);
  }
  /// A support's name ("clamped", ...) or a list of the fixed dofs (["uy", "rz"]).
  void Anchor(const char* name, AnchorMask& field, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    const toml::node* node = r_.Find(key);
    if (node == nullptr) return;
    static constexpr std::array<std::pair<const char*, Support>, 4> kSupports = {
        {{"free", Support::kFree},
         {"clamped", Support::kClamped},
         {"pinned", Support::kPinned},
         {"guided", Support::kGuided}}};
    static constexpr std::array<const char*, 6> kDofs = {"ux", "uy", "uz", "rx", "ry", "rz"};
    const std::string expected =
        "expected \"free\", \"clamped\", \"pinned\", \"guided\" or a list of dofs among "
        "\"ux\", \"uy\", \"uz\", \"rx\", \"ry\", \"rz\"";
    if (const std::optional<std::string> support = node->value<std::string>()) {
      for (const auto& [spelling, kind] : kSupports) {
        if (*support == spelling) {
          field = AnchorOf(kind);
          return;
        }
      }
      r_.Fail(key, expected);
    }
    const toml::array* array = node->as_array();
    r_.Require(array != nullptr, key, expected);
    field = AnchorMask{};
    for (const toml::node& element : *array) {
      const std::optional<std::string> dof = element.value<std::string>();
      const auto at =
          dof ? std::find_if(kDofs.begin(), kDofs.end(), [&](const char* d) { return *dof == d; })
              : kDofs.end();
      r_.Require(at != kDofs.end(), key, expected);
      field[at - kDofs.begin()] = true;
    }
  }
  /// A design key of the devices `fields` lists: read into the field of `kind`'s design, and
  /// refused, naming those devices, for any other kind.
  void Design(const char* name, StructureKind kind, DesignFields<double> fields,
              const NumberRule& rule, const char* meaning) {
    double unread = 0.0;
    Number(name, *ScopeDesign(kind, fields, unread), rule, meaning);
  }
  void Design(const char* name, StructureKind kind, DesignFields<int> fields,
              const IntegerRange& range, const char* meaning) {
    int unread = 0;
    Integer(name, *ScopeDesign(kind, fields, unread), range, meaning);
  }
  /// An array of tables ([[TABLE.NAME]]), each entry read by `visit` and refused unknown keys.
  template <class Entry, class Visit>
  void Entries(const char* name, std::vector<Entry>& entries, Visit visit, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    const toml::node* node = r_.Find(key);
    if (node == nullptr) return;
    const toml::array* array = node->as_array();
    r_.Require(array != nullptr && array->is_array_of_tables(), key,
               "expected an array of tables ([[" + key + "]])");
    entries.clear();
    for (std::size_t i = 0; i < array->size(); ++i) {
      const std::string table = key + "[" + std::to_string(i) + "]";
      KeyReader reader(r_, table, length_);
      Entry entry;
      visit(reader, entry);
      r_.RejectUnknownKeys(table, reader.names(), reader.chosen());
      entries.push_back(std::move(entry));
    }
  }
  void Pair(const char* name, std::optional<std::array<double, 2>>& field, const Bounds& first,
            const Bounds& second, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    const std::optional<std::vector<double>> values = r_.OptionalNumbers(key, 2);
    if (!values) return;
    const double a = (*values)[0], b = (*values)[1];
    r_.Require(a >= 0.0 && b >= 0.0, key, "each must be non-negative");
    r_.RequireWithin(key + "[0]", a, first);
    r_.RequireWithin(key + "[1]", b, second);
    field = std::array<double, 2>{a, b};
  }
  void Interval(const char* name, std::array<double, 2>& field, const Bounds& bounds, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    if (r_.Find(key) == nullptr) r_.FailMissing(key);
    const std::vector<double> values = *r_.OptionalNumbers(key, 2);
    r_.RequireWithin(key + "[0]", values[0], bounds);
    r_.RequireWithin(key + "[1]", values[1], bounds);
    r_.Require(values[0] < values[1], key, "must run from the smaller value to the larger");
    field = {values[0], values[1]};
  }
  void Position(const char* name, std::optional<double>& field, const char*) {
    if (!Reads(name)) return;
    const std::string key = Key(name);
    field = r_.OptionalNumber(key);
    r_.Require(!field || (*field >= 0.0 && *field <= length_), key,
               "must lie on the beam, in [0, " + FormatNumber(length_) + "]");
  }

 private:
  // `count` names (0: one or more), each a non-empty string.
  void ReadNames(const std::string& key, const toml::node& node, std::size_t count,
                 std::vector<std::string>& field) {
    const std::string expected = count > 0
                                     ? "expected an array of " + std::to_string(count) + " names"
                                     : "expected an array of one or more names";
    const toml::array* array = node.as_array();
    r_.Require(array != nullptr && (count > 0 ? array->size() == count : !array->empty()), key,
               expected);
    field.clear();
    for (const toml::node& element : *array) {
      r_.Require(element.is_string() && !element.value<std::string>()->empty(), key, expected);
      field.push_back(*element.value<std::string>());
    }
  }

  std::string Key(const char* name) const { return table_ + "." + name; }

  // The scope of one design key (its devices own it); the field to read it into, `unread` when
  // the scene's kind is none of them.
  template <class T>
  T* ScopeDesign(StructureKind kind, DesignFields<T> fields, T& unread) {
    T* field = ChosenDesign(kind, fields);
    design_owner_ = DesignOwner(fields);
    Scope(design_owner_.c_str(), field != nullptr, Unchosen::kRefused);
    return field != nullptr ? field : &unread;
  }

  // Whether the key is read: its owner chosen; otherwise skipped, or refused when given. Every
  // key asked about is a known one.
  bool Reads(const char* name) {
    if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(name);
    if (chosen_ &&
        std::find(chosen_names_.begin(), chosen_names_.end(), name) == chosen_names_.end()) {
      chosen_names_.push_back(name);
    }
    if (chosen_) return true;
    if (unchosen_ == Unchosen::kRefused) {
      r_.Require(r_.Find(Key(name)) == nullptr, Key(name),
                 std::string("only ") + owner_ + " takes it");
    }
    return false;
  }

  std::optional<double> Read(const std::string& key, const NumberRule& rule) const {
    const std::optional<double> value = r_.OptionalNumber(key);
    if (!value) return value;
    if (rule.sign == Sign::kPositive) r_.Require(*value > 0.0, key, "must be positive");
    if (rule.sign == Sign::kNonNegative) r_.Require(*value >= 0.0, key, "must be non-negative");
    if (rule.open) {
      r_.Require(*value > rule.bounds.lower && *value < rule.bounds.upper, key,
                 "must lie in (" + FormatNumber(rule.bounds.lower) + ", " +
                     FormatNumber(rule.bounds.upper) + ")");
    } else if (rule.range != nullptr) {
      r_.Require(*value >= rule.bounds.lower && *value <= rule.bounds.upper, key,
                 std::string("must lie in ") + rule.range);
    } else {
      r_.RequireWithin(key, *value, rule.bounds);
    }
    return value;
  }

  const TomlFieldReader& r_;
  std::string table_;
  double length_;
  const char* owner_ = "";
  std::string design_owner_;  // owner_ of a design key
  bool chosen_ = true;
  Unchosen unchosen_ = Unchosen::kSkipped;
  std::vector<std::string_view> names_;
  std::vector<std::string_view> chosen_names_;
};

}  // namespace cosmems::internal
