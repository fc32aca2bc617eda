#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cosmems/scene/scene_key_reference.hpp"
#include "scene_keys.hpp"
#include "toml_format.hpp"

namespace cosmems {
namespace internal {
namespace {

// A markdown row per key of one table, from its visit on a default scene.
class KeyReference {
 public:
  KeyReference(std::string& out, std::string table) : out_(out), table_(std::move(table)) {}

  void Scope(const char* owner, bool, Unchosen unchosen) {
    scope_ = std::string(unchosen == Unchosen::kRefused ? "only " : "with ") + owner + ": ";
  }

  void Required(const char* name, double&, const NumberRule& rule, const char* meaning) {
    Row(name, Accepts(rule), "required", meaning);
  }
  void Number(const char* name, double& field, const NumberRule& rule, const char* meaning) {
    Row(name, Accepts(rule), FormatNumber(field), meaning);
  }
  void Number(const char* name, std::optional<double>&, const NumberRule& rule,
              const char* fallback, const char* meaning) {
    Row(name, Accepts(rule), fallback, meaning);
  }
  void Integer(const char* name, int& field, const IntegerRange& range, const char* meaning) {
    Row(name, Accepts(range), std::to_string(field), meaning);
  }
  void Flag(const char* name, bool& field, const char* meaning) {
    Row(name, "`true` \\| `false`", field ? "`true`" : "`false`", meaning);
  }
  template <class Enum, std::size_t N>
  void Choice(const char* name, Enum& field, const std::array<Enum, N>& options, std::string_view,
              const char* meaning) {
    Row(name, Choices(options), std::string("`\"") + ToString(field) + "\"`", meaning);
  }
  template <class Enum, std::size_t N>
  void RequiredChoice(const char* name, Enum&, const std::array<Enum, N>& options, std::string_view,
                      const char* meaning) {
    Row(name, Choices(options), "required", meaning);
  }
  void Text(const char* name, std::string& field, const char* meaning) {
    Row(name, "a non-empty string", "`\"" + field + "\"`", meaning);
  }
  void Vector(const char* name, Eigen::Vector3d& field, const Bounds& bounds, const char* meaning) {
    Row(name, "`[x, y, z]`, each " + Range(bounds),
        "`[" + FormatNumber(field.x()) + ", " + FormatNumber(field.y()) + ", " +
            FormatNumber(field.z()) + "]`",
        meaning);
  }
  void Pair(const char* name, std::optional<std::array<double, 2>>&, const Bounds& first,
            const Bounds& second, const char* meaning) {
    Row(name, "`[a, b]`: " + Range(first) + "; " + Range(second), "none", meaning);
  }
  void Interval(const char* name, std::array<double, 2>&, const Bounds& bounds,
                const char* meaning) {
    Row(name, "`[from, to]`, each " + Range(bounds) + ", from < to", "required", meaning);
  }
  void Position(const char* name, std::optional<double>&, const char* meaning) {
    Row(name, "0 … `structure.length` m", "see meaning", meaning);
  }
  void RequiredVector(const char* name, Eigen::Vector3d&, const Bounds& bounds,
                      const char* meaning) {
    Row(name, "`[x, y, z]`, each " + Range(bounds), "required", meaning);
  }
  void Integer(const char* name, std::optional<int>&, const IntegerRange& range,
               const char* fallback, const char* meaning) {
    Row(name, "integer, " + std::to_string(range.lower) + " … " + std::to_string(range.upper),
        fallback, meaning);
  }
  void RequiredText(const char* name, std::string&, const char* meaning) {
    Row(name, "a non-empty string", "required", meaning);
  }
  void OptionalText(const char* name, std::optional<std::string>&, const char* fallback,
                    const char* meaning) {
    Row(name, "a non-empty string", fallback, meaning);
  }
  void Names(const char* name, std::vector<std::string>&, std::size_t count, const char* meaning) {
    Row(name, count > 0 ? "`[" + std::to_string(count) + " names]`" : "`[names]`", "required",
        meaning);
  }
  void OptionalNames(const char* name, std::vector<std::string>&, const char* fallback,
                     const char* meaning) {
    Row(name, "`[names]`", fallback, meaning);
  }
  void Anchor(const char* name, AnchorMask&, const char* meaning) {
    Row(name, "a support or `[dofs]`", "`\"free\"`", meaning);
  }
  // One row for a design key, whatever the number of devices that read it.
  void Design(const char* name, StructureKind, DesignFields<double> fields, const NumberRule& rule,
              const char* meaning) {
    DesignRow(
        name, Accepts(rule), fields, [](double v) { return FormatNumber(v); }, meaning);
  }
  void Design(const char* name, StructureKind, DesignFields<int> fields, const IntegerRange& range,
              const char* meaning) {
    DesignRow(
        name, Accepts(range), fields, [](int v) { return std::to_string(v); }, meaning);
  }
  // The entry's keys follow as TABLE.NAME[].KEY, in the entry's scope.
  template <class Entry, class Visit>
  void Entries(const char* name, std::vector<Entry>&, Visit visit, const char* meaning) {
    Row(name, "an array of tables", "none", meaning);
    KeyReference entry(out_, table_ + "." + name + "[]");
    entry.scope_ = scope_;
    Entry defaults;
    visit(entry, defaults);
  }

 private:
  static std::string Range(const Bounds& b) {
    const std::string unit = *b.unit != '\0' ? std::string(" ") + b.unit : "";
    return FormatNumber(b.lower) + " … " + FormatNumber(b.upper) + unit;
  }
  static std::string Accepts(const NumberRule& rule) {
    const std::string unit = *rule.bounds.unit != '\0' ? std::string(" ") + rule.bounds.unit : "";
    std::string range = Range(rule.bounds);
    if (rule.open) {
      range = "(" + FormatNumber(rule.bounds.lower) + ", " + FormatNumber(rule.bounds.upper) + ")" +
              unit;
    } else if (rule.range != nullptr) {
      range = std::string(rule.range) + unit;
    }
    switch (rule.sign) {
      case Sign::kPositive:
        return "> 0, " + range;
      case Sign::kNonNegative:
        return "≥ 0, " + range;
      case Sign::kAny:
        break;
    }
    return range;
  }
  static std::string Accepts(const IntegerRange& range) {
    return range.upper == range.lower + 1
               ? std::to_string(range.lower) + " or " + std::to_string(range.upper)
               : "integer, " + std::to_string(range.lower) + " … " + std::to_string(range.upper);
  }
  // The default, or the devices' when they differ: "1e-04 (`folded_flexure`, `crab_leg`),
  // 2e-04 (`accelerometer`)".
  template <class T, class Format>
  void DesignRow(const char* name, const std::string& accepts, DesignFields<T> fields,
                 Format format, const char* meaning) {
    scope_ = "only " + DesignOwner(fields) + ": ";
    std::vector<std::pair<T, std::string>> defaults;  // each value with its devices
    for (const DesignField<T>& f : fields) {
      const std::string kind = std::string("`") + ToString(f.kind) + "`";
      const auto same = std::find_if(defaults.begin(), defaults.end(),
                                     [&](const auto& d) { return d.first == *f.field; });
      if (same == defaults.end()) {
        defaults.emplace_back(*f.field, kind);
      } else {
        same->second += ", " + kind;
      }
    }
    std::string text = format(defaults.front().first);
    if (defaults.size() > 1) {
      text.clear();
      for (const auto& [value, kinds] : defaults) {
        text += (text.empty() ? "" : ", ") + format(value) + " (" + kinds + ")";
      }
    }
    Row(name, accepts, text, meaning);
  }
  template <class Enum, std::size_t N>
  static std::string Choices(const std::array<Enum, N>& options) {
    std::string out;
    for (std::size_t i = 0; i < N; ++i) {
      out += (i > 0 ? " \\| `\"" : "`\"") + std::string(ToString(options[i])) + "\"`";
    }
    return out;
  }
  void Row(const char* name, const std::string& accepts, const std::string& fallback,
           const char* meaning) {
    out_ += "| `" + table_ + "." + name + "` | " + accepts + " | " + fallback + " | " + scope_ +
            meaning + " |\n";
  }

  std::string& out_;
  std::string table_;
  std::string scope_;
};

template <class Visit>
void Table(std::string& out, const char* table, Visit visit) {
  KeyReference reference(out, table);
  visit(reference);
}

}  // namespace
}  // namespace internal

std::string SceneKeyReference() {
  using namespace internal;
  Scene s;
  SceneTimeFunction f;
  ContactEffect contact;
  StictionEffect stiction;
  ElectrostaticEffect electrostatic;
  CasimirEffect casimir;
  VanDerWaalsEffect van_der_waals;
  DampingEffect damping;
  SqueezeFilmEffect squeeze_film;
  SceneDevice device;
  std::string out = "| key | accepts | default | meaning |\n|---|---|---|---|\n";
  Table(out, "structure", [&](auto& v) { VisitStructure(v, s.structure); });
  Table(out, "material", [&](auto& v) { VisitMaterial(v, s.material); });
  // Named materials of a frame take the keys of [material].
  Table(out, "materials.NAME", [&](auto& v) { VisitMaterial(v, s.material); });
  Table(out, "model", [&](auto& v) { VisitModel(v, s.model); });
  Table(out, "loads", [&](auto& v) { VisitLoads(v, s.loads, f, f.kind, s.structure.kind); });
  Table(out, "effects", [&](auto& v) { VisitEffects(v, s.effects, StructureKind::kFrame); });
  Table(out, "effects.contact", [&](auto& v) { VisitContact(v, contact); });
  Table(out, "effects.stiction", [&](auto& v) { VisitStiction(v, stiction); });
  Table(out, "effects.electrostatic",
        [&](auto& v) { VisitElectrostatic(v, electrostatic, StructureKind::kFrame); });
  Table(out, "effects.casimir", [&](auto& v) { VisitCasimir(v, casimir); });
  Table(out, "effects.van_der_waals", [&](auto& v) { VisitVanDerWaals(v, van_der_waals); });
  Table(out, "effects.damping", [&](auto& v) { VisitDamping(v, damping); });
  Table(out, "effects.squeeze_film", [&](auto& v) { VisitSqueezeFilm(v, squeeze_film); });
  Table(out, "analysis", [&](auto& v) {
    // As a transient sees them: another integrator's parameters refused.
    VisitAnalysis(v, s.analysis, AnalysisType::kTransient, s.analysis.integrator,
                  StructureKind::kFrame);
  });
  Table(out, "device", [&](auto& v) { VisitDevice(v, device); });
  return out;
}

}  // namespace cosmems
