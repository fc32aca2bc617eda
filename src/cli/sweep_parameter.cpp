#include "sweep_parameter.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "cli_errors.hpp"
#include "csv_file.hpp"
#include "normal_quantile.hpp"

namespace cosmems::internal {
namespace {

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator)) parts.push_back(part);
  if (!text.empty() && text.back() == separator) parts.emplace_back();
  return parts;
}

}  // namespace

SweepParameter::SweepParameter(std::string key, std::string spec)
    : key_(std::move(key)), spec_(std::move(spec)) {
  auto fail = [&](const std::string& why) {
    throw CliInputError("--vary " + key_ + "=" + spec_ + ": " + why);
  };
  auto number = [&](const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
      fail("\"" + text + "\" is not a finite number");
    }
    return value;
  };
  if (key_.empty()) fail("the key is empty");
  if (!spec_.empty() && spec_.front() == '[') {
    toml::table parsed;
    try {
      parsed = toml::parse("v = " + spec_);
    } catch (const toml::parse_error& error) {
      fail("not a TOML list: " + std::string(error.description()));
    }
    const toml::array* list = parsed["v"].as_array();
    if (list == nullptr || list->empty()) fail("expected a non-empty list of values");
    for (const toml::node& element : *list) {
      if (element.is_integer()) {
        values_.emplace_back(*element.value<std::int64_t>());
      } else if (element.is_floating_point()) {
        values_.emplace_back(*element.value<double>());
      } else if (element.is_string()) {
        values_.emplace_back(*element.value<std::string>());
      } else if (element.is_boolean()) {
        values_.emplace_back(*element.value<bool>());
      } else {
        fail("a list of numbers, strings or booleans is expected");
      }
    }
    return;
  }
  std::vector<std::string> parts = Split(spec_, ':');
  const bool logarithmic = !parts.empty() && parts.front() == "log";
  if (logarithmic || (parts.size() == 3 && parts.front() != "uniform" &&
                      parts.front() != "normal" && parts.front() != "lognormal")) {
    if (logarithmic) parts.erase(parts.begin());
    if (parts.size() != 3) fail("a grid is A:B:N or log:A:B:N");
    const double a = number(parts[0]), b = number(parts[1]), n = number(parts[2]);
    if (n < 1 || n != std::floor(n) || n > 1e6) fail("N must be an integer from 1 to 1e6");
    if (logarithmic && !(a > 0.0 && b > 0.0)) fail("a logarithmic grid needs A > 0 and B > 0");
    const int count = static_cast<int>(n);
    const double step = count > 1 ? (b - a) / (count - 1) : 0.0;
    // Integer ends and step give integer values, as an integer key (model.elements) needs.
    const bool integral = !logarithmic && a == std::floor(a) && step == std::floor(step) &&
                          std::abs(a) < 1e15 && std::abs(b) < 1e15;
    for (int i = 0; i < count; ++i) {
      const double s = count > 1 ? static_cast<double>(i) / (count - 1) : 0.0;
      double value = logarithmic ? a * std::pow(b / a, s) : a + i * step;
      if (i == count - 1 && count > 1) value = b;  // the end exactly, not its rounding
      if (integral) {
        values_.emplace_back(static_cast<std::int64_t>(std::llround(value)));
      } else {
        values_.emplace_back(value);
      }
    }
    return;
  }
  const std::string& name = parts.front();
  auto expect = [&](std::size_t count, const char* form) {
    if (parts.size() != count + 1) fail(std::string("expected ") + form);
  };
  if (name == "uniform") {
    expect(2, "uniform:A:B");
    kind_ = Kind::kUniform;
    low_ = number(parts[1]);
    high_ = number(parts[2]);
    if (!(low_ < high_)) fail("uniform:A:B needs A < B");
  } else if (name == "normal") {
    expect(2, "normal:MEAN:SIGMA");
    kind_ = Kind::kNormal;
    mean_ = number(parts[1]);
    sigma_ = number(parts[2]);
    if (!(sigma_ > 0.0)) fail("SIGMA must be positive");
  } else if (name == "lognormal") {
    expect(2, "lognormal:MEAN:SIGMA (of the value)");
    kind_ = Kind::kLogNormal;
    const double mean = number(parts[1]), sigma = number(parts[2]);
    if (!(mean > 0.0 && sigma > 0.0)) fail("a log-normal value needs MEAN > 0 and SIGMA > 0");
    // The normal of log(value) with the value's mean and standard deviation.
    const double variance = std::log1p(sigma * sigma / (mean * mean));
    sigma_ = std::sqrt(variance);
    mean_ = std::log(mean) - 0.5 * variance;
  } else if (name == "truncnormal") {
    expect(4, "truncnormal:MEAN:SIGMA:LO:HI");
    kind_ = Kind::kTruncatedNormal;
    mean_ = number(parts[1]);
    sigma_ = number(parts[2]);
    const double lo = number(parts[3]), hi = number(parts[4]);
    if (!(sigma_ > 0.0)) fail("SIGMA must be positive");
    if (!(lo < hi)) fail("LO must be below HI");
    low_ = NormalCdf((lo - mean_) / sigma_);
    high_ = NormalCdf((hi - mean_) / sigma_);
    if (!(high_ - low_ > 1e-12)) fail("[LO, HI] holds no probability of the normal");
  } else {
    fail(
        "expected A:B:N, log:A:B:N, [v1, v2, ...], uniform:A:B, normal:MEAN:SIGMA, "
        "lognormal:MEAN:SIGMA or truncnormal:MEAN:SIGMA:LO:HI");
  }
}

double SweepParameter::Quantile(double u) const {
  switch (kind_) {
    case Kind::kUniform:
      return low_ + u * (high_ - low_);
    case Kind::kNormal:
      return mean_ + sigma_ * NormalQuantile(u);
    case Kind::kLogNormal:
      return std::exp(mean_ + sigma_ * NormalQuantile(u));
    case Kind::kTruncatedNormal: {
      // Inverse transform within [Phi(alpha), Phi(beta)], kept off its ends by rounding.
      const double p = low_ + u * (high_ - low_);
      return mean_ + sigma_ * NormalQuantile(std::clamp(p, 1e-300, 1.0 - 1e-16));
    }
    case Kind::kGrid:
      break;
  }
  return std::nan("");
}

nlohmann::json SweepParameter::Nominal() const {
  return IsGrid() ? values_.front() : nlohmann::json(Quantile(0.5));
}

std::string TomlLiteral(const nlohmann::json& value) {
  if (value.is_string()) return value.dump();  // JSON's escapes are TOML's basic-string ones
  if (!value.is_number_float()) return value.dump();
  std::string literal = CsvFile::Number(value.get<double>());
  // TOML reads "3" as an integer: a float keeps a point or an exponent (or is inf or nan).
  if (literal.find_first_of(".ein") == std::string::npos) literal += ".0";
  return literal;
}

}  // namespace cosmems::internal
