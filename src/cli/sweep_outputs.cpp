#include "sweep_outputs.hpp"

#include <cstdlib>

namespace cosmems::internal {
namespace {

std::optional<double> Number(const nlohmann::ordered_json& value) {
  if (value.is_number()) return value.get<double>();
  if (value.is_boolean()) return value.get<bool>() ? 1.0 : 0.0;
  return std::nullopt;
}

constexpr const char* kListed = "frequencies_hz";

}  // namespace

std::vector<std::pair<std::string, double>> NumericOutputs(const nlohmann::ordered_json& result) {
  std::vector<std::pair<std::string, double>> outputs;
  if (!result.is_object()) return outputs;
  for (const auto& [name, value] : result.items()) {
    if (const std::optional<double> x = Number(value)) outputs.emplace_back(name, *x);
    if (name == kListed && value.is_array()) {
      for (std::size_t i = 0; i < value.size(); ++i) {
        if (const std::optional<double> x = Number(value[i])) {
          outputs.emplace_back(name + "[" + std::to_string(i) + "]", *x);
        }
      }
    }
  }
  return outputs;
}

std::optional<double> OutputValue(const nlohmann::ordered_json& result, const std::string& field) {
  if (!result.is_object()) return std::nullopt;
  const std::size_t bracket = field.find('[');
  const std::string name = field.substr(0, bracket);
  const auto found = result.find(name);
  if (found == result.end()) return std::nullopt;
  if (bracket == std::string::npos) return Number(*found);
  if (field.back() != ']' || !found->is_array()) return std::nullopt;
  const std::string digits = field.substr(bracket + 1, field.size() - bracket - 2);
  char* end = nullptr;
  const unsigned long i = std::strtoul(digits.c_str(), &end, 10);
  if (digits.empty() || *end != '\0' || i >= found->size()) return std::nullopt;
  return Number((*found)[i]);
}

}  // namespace cosmems::internal
