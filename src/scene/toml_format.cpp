#include "toml_format.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string_view>

namespace cosmems::internal {
namespace {

std::string QuoteString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
          std::array<char, 8> escaped{};
          std::snprintf(escaped.data(), escaped.size(), "\\u%04X", static_cast<unsigned>(c));
          out += escaped.data();
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

std::string FormatFloat(double value) {
  std::string text = FormatNumber(value);
  // "20" would read as an integer: keep floats recognisable, as TOML writes them.
  if (text.find_first_not_of("-0123456789") == std::string::npos) text += ".0";
  return text;
}

std::string FormatNumber(double value) {
  std::array<char, 32> buffer{};
  const std::to_chars_result end =
      std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return {buffer.data(), end.ptr};
}

bool IsBareKey(std::string_view key) {
  if (key.empty()) return false;
  for (const char c : key) {
    const bool bare = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '-';
    if (!bare) return false;
  }
  return true;
}

std::string FormatKey(std::string_view key) {
  return IsBareKey(key) ? std::string(key) : QuoteString(std::string(key));
}

std::string FormatToml(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::string:
      return QuoteString(*node.value<std::string>());
    case toml::node_type::integer:
      return std::to_string(*node.value<std::int64_t>());
    case toml::node_type::floating_point:
      return FormatFloat(*node.value<double>());
    case toml::node_type::boolean:
      return *node.value<bool>() ? "true" : "false";
    case toml::node_type::array: {
      std::string out = "[";
      for (const toml::node& element : *node.as_array()) {
        if (out.size() > 1) out += ", ";
        out += FormatToml(element);
      }
      return out + "]";
    }
    case toml::node_type::table: {
      const toml::table& table = *node.as_table();
      if (table.empty()) return "{}";
      std::string out = "{ ";
      bool first = true;
      for (const auto& [key, value] : table) {
        if (!first) out += ", ";
        first = false;
        out += FormatKey(key.str()) + " = " + FormatToml(value);
      }
      return out + " }";
    }
    default: {  // dates and times: toml++ prints them in TOML syntax
      std::ostringstream out;
      node.visit([&out](const auto& value) { out << value; });
      return out.str();
    }
  }
}

}  // namespace cosmems::internal
