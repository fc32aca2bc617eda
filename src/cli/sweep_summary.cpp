#include "sweep_summary.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "sweep_outputs.hpp"

namespace cosmems::internal {
namespace {

// The p-quantile of sorted values, linear between order statistics (Hyndman & Fan's type 7).
double Quantile(const std::vector<double>& sorted, double p) {
  const double h = (sorted.size() - 1) * p;
  const auto below = static_cast<std::size_t>(std::floor(h));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (h - below) * (sorted[above] - sorted[below]);
}

nlohmann::ordered_json Statistics(std::vector<double> values) {
  const double n = static_cast<double>(values.size());
  double sum = 0.0;
  for (const double x : values) sum += x;
  const double mean = sum / n;  // a constant output's mean is that constant, its std 0
  double squares = 0.0;
  for (const double x : values) squares += (x - mean) * (x - mean);
  std::sort(values.begin(), values.end());
  nlohmann::ordered_json quantiles;
  for (const auto& [name, p] :
       {std::pair{"p01", 0.01}, {"p05", 0.05}, {"p50", 0.5}, {"p95", 0.95}, {"p99", 0.99}}) {
    quantiles[name] = Quantile(values, p);
  }
  return {{"mean", mean},
          {"std", values.size() > 1 ? std::sqrt(squares / (n - 1.0)) : 0.0},
          {"min", values.front()},
          {"max", values.back()},
          {"quantiles", quantiles}};
}

// The keys whose value is a number in every row and not the same in all, in the first row's
// order: the plane's unknowns.
std::vector<std::string> NumericKeys(const std::vector<SweepRow>& rows) {
  std::vector<std::string> keys;
  if (rows.empty()) return keys;
  for (const auto& [key, first] : rows.front().parameters.items()) {
    bool numeric = true, varies = false;
    for (const SweepRow& row : rows) {
      const auto value = row.parameters.find(key);
      numeric = numeric && value != row.parameters.end() && value->is_number();
      varies = varies || (numeric && value->get<double>() != first.get<double>());
    }
    if (numeric && varies) keys.push_back(key);
  }
  return keys;
}

// d(output)/d(key) of the least-squares plane through the rows that have the output; empty
// when they do not determine it.
nlohmann::ordered_json Sensitivities(const std::vector<const SweepRow*>& rows,
                                     const std::vector<double>& output,
                                     const std::vector<std::string>& keys) {
  const int n = static_cast<int>(rows.size()), p = static_cast<int>(keys.size());
  if (p == 0 || n <= p + 1) return nullptr;
  Eigen::MatrixXd a(n, p + 1);
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) {
    a(i, 0) = 1.0;
    for (int k = 0; k < p; ++k) a(i, k + 1) = rows[i]->parameters[keys[k]].get<double>();
    b[i] = output[i];
  }
  // Columns scaled to unit size, so that a length in metres and a voltage rank alike.
  const Eigen::VectorXd scale = a.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a * scale.cwiseInverse().asDiagonal());
  if (qr.rank() < p + 1) return nullptr;
  const Eigen::VectorXd x = qr.solve(b).cwiseQuotient(scale);
  nlohmann::ordered_json out;
  for (int k = 0; k < p; ++k) out[keys[k]] = x[k + 1];
  return out;
}

}  // namespace

nlohmann::ordered_json SummarizeSweep(const std::vector<SweepRow>& rows,
                                      const std::vector<SweepCondition>& conditions) {
  nlohmann::ordered_json summary;
  summary["samples"] = rows.size();
  summary["failed"] =
      std::count_if(rows.begin(), rows.end(), [](const SweepRow& r) { return !r.ok(); });
  if (!conditions.empty()) {
    const auto met = std::count_if(rows.begin(), rows.end(), [&](const SweepRow& row) {
      return row.ok() && std::all_of(conditions.begin(), conditions.end(),
                                     [&](const SweepCondition& c) { return c.Met(row.result); });
    });
    summary["yield"] = rows.empty() ? 0.0 : static_cast<double>(met) / rows.size();
  }
  // Each output's values and the rows they came from, in the order fields first appear.
  std::vector<std::string> fields;
  std::map<std::string, std::pair<std::vector<double>, std::vector<const SweepRow*>>> columns;
  for (const SweepRow& row : rows) {
    if (!row.ok()) continue;
    for (const auto& [field, value] : NumericOutputs(row.result)) {
      auto [entry, fresh] = columns.try_emplace(field);
      if (fresh) fields.push_back(field);
      entry->second.first.push_back(value);
      entry->second.second.push_back(&row);
    }
  }
  const std::vector<std::string> keys = NumericKeys(rows);
  nlohmann::ordered_json outputs = nlohmann::ordered_json::object();
  nlohmann::ordered_json sensitivities = nlohmann::ordered_json::object();
  for (const std::string& field : fields) {
    const auto& [values, from] = columns.at(field);
    outputs[field] = Statistics(values);
    nlohmann::ordered_json slopes = Sensitivities(from, values, keys);
    if (!slopes.is_null()) sensitivities[field] = std::move(slopes);
  }
  summary["outputs"] = std::move(outputs);
  summary["sensitivities"] = std::move(sensitivities);
  return summary;
}

}  // namespace cosmems::internal
