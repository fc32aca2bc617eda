#include "sweep_condition.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "cli_errors.hpp"
#include "sweep_outputs.hpp"

namespace cosmems::internal {
namespace {

std::string Trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// A result's field as NumericOutputs names it: a word, maybe with an index ("name[2]").
bool Field(const std::string& text) {
  const std::size_t bracket = text.find('[');
  const std::string word = text.substr(0, bracket);
  auto word_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  if (word.empty() || !std::all_of(word.begin(), word.end(), word_char)) return false;
  if (bracket == std::string::npos) return true;
  const std::string index = text.substr(bracket + 1);
  return index.size() >= 2 && index.back() == ']' &&
         std::all_of(index.begin(), index.end() - 1,
                     [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

}  // namespace

SweepCondition::SweepCondition(const std::string& text) : text_(text) {
  // Two-character operators first, so that ">=" is not read as ">".
  constexpr std::array<const char*, 6> kOperators = {">=", "<=", "==", "!=", ">", "<"};
  for (const char* op : kOperators) {
    const std::size_t at = text.find(op);
    if (at == std::string::npos) continue;
    op_ = op;
    field_ = Trim(text.substr(0, at));
    const std::string number = Trim(text.substr(at + op_.size()));
    char* end = nullptr;
    bound_ = std::strtod(number.c_str(), &end);
    if (!Field(field_) || number.empty() || *end != '\0' || !std::isfinite(bound_)) break;
    return;
  }
  throw CliInputError("--spec " + text +
                      ": expected FIELD OP NUMBER, OP one of >=, <=, >, <, ==, != "
                      "(pullin_voltage_v>=20)");
}

bool SweepCondition::Met(const nlohmann::ordered_json& result) const {
  const std::optional<double> value = OutputValue(result, field_);
  if (!value) return false;
  const double x = *value;
  if (op_ == ">=") return x >= bound_;
  if (op_ == "<=") return x <= bound_;
  if (op_ == "==") return x == bound_;
  if (op_ == "!=") return x != bound_;
  if (op_ == ">") return x > bound_;
  return x < bound_;
}

}  // namespace cosmems::internal
