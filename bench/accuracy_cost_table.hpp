#pragma once

// The accuracy-versus-cost table: one row per problem and setting, its Pareto front, and the CSV
// and Markdown files that bench/accuracy_cost.gp and the README read.

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace cosmems::bench {

/// A setting of the sweep as (key, value) pairs in a fixed order; values hold no spaces. The first
/// value names the series the setting belongs to in the plots (a theory, a series order, a time
/// integrator), the other pairs move along it.
using Settings = std::vector<std::pair<std::string, std::string>>;

/// "key=value key=value": the benchmark's label and the CSV's settings column.
inline std::string SettingsLabel(const Settings& settings) {
  std::string out;
  for (const auto& [key, value] : settings) {
    if (!out.empty()) out += ' ';
    out.append(key).append("=").append(value);
  }
  return out;
}

/// The inverse of SettingsLabel; tokens without '=' are ignored.
inline Settings ParseSettings(const std::string& label) {
  Settings out;
  std::istringstream in(label);
  for (std::string token; in >> token;) {
    const auto eq = token.find('=');
    if (eq != std::string::npos) out.emplace_back(token.substr(0, eq), token.substr(eq + 1));
  }
  return out;
}

/// What a problem of the report measures, for the Markdown file's headings.
struct ProblemInfo {
  std::string name;   ///< the benchmark name's first component, e.g. "frequencies"
  std::string title;  ///< one line: the structure and the quantity
  std::string error;  ///< what rel_error measures, against which reference
  std::string timed;  ///< what one timed call is
};

/// One setting of one problem: its error against the reference and what it costs.
struct AccuracyCostRow {
  std::string problem;
  Settings settings;
  double rel_error = 0.0;
  double time_us = 0.0;          ///< median CPU time of one timed call (a step or a solve)
  double real_time_us = 0.0;     ///< median real time of the same call
  double calls_per_tick = 1.0;   ///< timed calls per 1 ms tick: steps per ms, or one solve
  int repetitions = 1;           ///< the runs the median is taken over
  bool failed = false;           ///< the benchmark skipped with an error
  std::string message;           ///< that error
  bool on_pareto_front = false;  ///< no other row of the problem is as cheap and as accurate
  int series_index = 0;          ///< 1-based rank of the first setting's value (NumberSeries)

  /// The cost of one 1 kHz haptic tick with this setting [us].
  double TickCostUs() const { return time_us * calls_per_tick; }
};

/// Numbers each problem's series (the first setting's value) 1, 2, ... in the order of their
/// first rows in `rows`: given the order of the sweep, every run colours a series alike.
inline void NumberSeries(std::vector<AccuracyCostRow>& rows) {
  std::map<std::string, std::vector<std::string>> seen;
  for (AccuracyCostRow& row : rows) {
    const std::string series = row.settings.empty() ? "" : row.settings.front().second;
    std::vector<std::string>& names = seen[row.problem];
    auto it = std::find(names.begin(), names.end(), series);
    if (it == names.end()) it = names.insert(names.end(), series);
    row.series_index = static_cast<int>(it - names.begin()) + 1;
  }
}

/// Errors that agree to six digits are the same accuracy: settings that differ only in what the
/// error does not see (the step of an exact propagation, say) then compare by cost alone.
inline bool MoreAccurate(double a, double b) { return a < b * (1.0 - 1e-6); }

/// Marks, within each problem, the rows that no other row dominates in (tick cost, error):
/// a row is dominated by one that is no worse in both and better in one. Failed rows never
/// enter the front.
inline void MarkParetoFront(std::vector<AccuracyCostRow>& rows) {
  for (AccuracyCostRow& row : rows) {
    row.on_pareto_front = !row.failed;
    for (const AccuracyCostRow& other : rows) {
      if (!row.on_pareto_front) break;
      if (&other == &row || other.failed || other.problem != row.problem) continue;
      const bool no_worse =
          other.TickCostUs() <= row.TickCostUs() && !MoreAccurate(row.rel_error, other.rel_error);
      const bool better =
          other.TickCostUs() < row.TickCostUs() || MoreAccurate(other.rel_error, row.rel_error);
      if (no_worse && better) row.on_pareto_front = false;
    }
  }
}

/// The most accurate row of `problem` whose tick cost fits `budget_us` (of equally accurate
/// ones the cheapest), or nullptr.
inline const AccuracyCostRow* BestWithin(const std::vector<AccuracyCostRow>& rows,
                                         const std::string& problem, double budget_us) {
  const AccuracyCostRow* best = nullptr;
  for (const AccuracyCostRow& row : rows) {
    if (row.failed || row.problem != problem || row.TickCostUs() > budget_us) continue;
    if (!best || MoreAccurate(row.rel_error, best->rel_error) ||
        (!MoreAccurate(best->rel_error, row.rel_error) && row.TickCostUs() < best->TickCostUs())) {
      best = &row;
    }
  }
  return best;
}

/// Rows grouped by problem in the order of `problems` (problems not listed follow by name),
/// each group by increasing tick cost: the order of the CSV and of the Markdown tables.
inline std::vector<AccuracyCostRow> SortedForReport(std::vector<AccuracyCostRow> rows,
                                                    const std::vector<ProblemInfo>& problems) {
  std::map<std::string, std::size_t> rank;
  for (const ProblemInfo& p : problems) rank.emplace(p.name, rank.size());
  auto order = [&](const AccuracyCostRow& r) {
    const auto it = rank.find(r.problem);
    return it == rank.end() ? problems.size() : it->second;
  };
  std::stable_sort(rows.begin(), rows.end(),
                   [&](const AccuracyCostRow& a, const AccuracyCostRow& b) {
                     if (order(a) != order(b)) return order(a) < order(b);
                     if (a.problem != b.problem) return a.problem < b.problem;
                     if (a.failed != b.failed) return b.failed;
                     return a.TickCostUs() < b.TickCostUs();
                   });
  return rows;
}

namespace internal {

inline std::string Format(const char* format, double value) {
  std::array<char, 64> buffer{};
  std::snprintf(buffer.data(), buffer.size(), format, value);
  return buffer.data();
}

/// A time in us with a unit that keeps three significant digits readable.
inline std::string FormatTime(double us) {
  if (us < 1.0) return Format("%.3g ns", 1e3 * us);
  if (us < 1e3) return Format("%.3g us", us);
  return Format("%.3g ms", 1e-3 * us);
}

inline std::string SettingValue(const Settings& settings, const std::string& key) {
  for (const auto& [k, v] : settings) {
    if (k == key) return v;
  }
  return "";
}

/// The settings' keys of `problem` in their first order of appearance.
inline std::vector<std::string> SettingKeys(const std::vector<AccuracyCostRow>& rows,
                                            const std::string& problem) {
  std::vector<std::string> keys;
  for (const AccuracyCostRow& row : rows) {
    if (row.problem != problem) continue;
    for (const auto& [key, value] : row.settings) {
      if (std::find(keys.begin(), keys.end(), key) == keys.end()) keys.push_back(key);
    }
  }
  return keys;
}

}  // namespace internal

/// problem,settings,series,series_index,series_label,rel_error,median_cpu_us,median_real_us,
/// timed,calls_per_tick,tick_cost_us,repetitions,on_pareto_front,status: one line per row, in
/// the order given. series is the first setting's value and series_index its number
/// (NumberSeries); series_label, "key=value" of that setting, is on the series' first line only,
/// to label the plots; tick_cost_us comes from the CPU time; a failed row has empty figures.
inline bool WriteCsv(const std::string& path, const std::vector<AccuracyCostRow>& rows) {
  std::ofstream out(path);
  out << "problem,settings,series,series_index,series_label,rel_error,median_cpu_us,"
         "median_real_us,timed,calls_per_tick,tick_cost_us,repetitions,on_pareto_front,status\n";
  std::set<std::pair<std::string, int>> labelled;
  for (const AccuracyCostRow& row : rows) {
    const std::string series = row.settings.empty() ? "" : row.settings.front().second;
    const bool first = labelled.emplace(row.problem, row.series_index).second;
    const std::string label =
        first && !row.settings.empty() ? SettingsLabel({row.settings.front()}) : "";
    out << row.problem << ',' << SettingsLabel(row.settings) << ',' << series << ','
        << row.series_index << ',' << label << ',';
    if (row.failed) {
      out << ",,,";
    } else {
      out << internal::Format("%.6e", row.rel_error) << ',' << internal::Format("%.6g", row.time_us)
          << ',' << internal::Format("%.6g", row.real_time_us) << ',';
    }
    out << (row.calls_per_tick == 1.0 ? "solve" : "step") << ','
        << internal::Format("%.6g", row.calls_per_tick) << ',';
    if (!row.failed) out << internal::Format("%.6g", row.TickCostUs());
    out << ',' << row.repetitions << ',' << (row.on_pareto_front ? 1 : 0) << ','
        << (row.failed ? "failed" : "ok") << '\n';
  }
  return static_cast<bool>(out);
}

/// What the Markdown file says about how the figures were made.
struct ReportContext {
  std::string command;        ///< the command that produced the figures
  std::string machine;        ///< CPUs and clock, as Google Benchmark saw them
  std::string date;           ///< UTC
  double tick_budget_us = 0;  ///< the share of a 1 ms tick the physics may take
};

/// One table per problem (in the order of `problems`), rows by increasing tick cost, the Pareto
/// front marked, and the most accurate setting within the tick budget under each table.
inline bool WriteMarkdown(const std::string& path, const std::vector<AccuracyCostRow>& rows,
                          const std::vector<ProblemInfo>& problems, const ReportContext& context) {
  std::ofstream out(path);
  out << "# Accuracy against cost\n\n"
      << "Produced by `" << context.command << "` on " << context.date << " (" << context.machine
      << "). Times are medians over the repetitions of Google Benchmark's CPU time per timed "
         "call (the CSV also has the real time, which on a shared machine adds the time the "
         "process waited). A tick is 1 ms of a 1 kHz haptic loop and costs one solve, or the "
         "steps that cover 1 ms. Pareto: no other setting of the problem is both as cheap per "
         "tick and as accurate. Budget: "
      << internal::FormatTime(context.tick_budget_us) << " per tick.\n";
  for (const ProblemInfo& problem : problems) {
    const std::vector<std::string> keys = internal::SettingKeys(rows, problem.name);
    if (keys.empty()) continue;
    bool stepped = false;
    for (const AccuracyCostRow& row : rows) {
      if (row.problem == problem.name && row.calls_per_tick != 1.0) stepped = true;
    }
    out << "\n## " << problem.name << ": " << problem.title << "\n\n"
        << "Error: " << problem.error << ". Timed: " << problem.timed << ".\n\n|";
    for (const std::string& key : keys) out << ' ' << key << " |";
    out << " rel. error | CPU time" << (stepped ? " per step | per tick" : " per solve")
        << " | Pareto |\n|";
    for (std::size_t i = 0; i < keys.size() + (stepped ? 4 : 3); ++i) out << "---|";
    out << '\n';
    for (const AccuracyCostRow& row : rows) {
      if (row.problem != problem.name) continue;
      out << '|';
      for (const std::string& key : keys)
        out << ' ' << internal::SettingValue(row.settings, key) << " |";
      if (row.failed) {
        out << " failed: " << row.message << " |" << (stepped ? " | |" : " |") << " |\n";
        continue;
      }
      out << ' ' << internal::Format("%.2e", row.rel_error) << " | "
          << internal::FormatTime(row.time_us) << " |";
      if (stepped) out << ' ' << internal::FormatTime(row.TickCostUs()) << " |";
      out << (row.on_pareto_front ? " yes |" : " |") << '\n';
    }
    const AccuracyCostRow* best = BestWithin(rows, problem.name, context.tick_budget_us);
    out << "\nMost accurate within " << internal::FormatTime(context.tick_budget_us)
        << " per tick: ";
    if (best) {
      out << '`' << SettingsLabel(best->settings) << "`, error "
          << internal::Format("%.2e", best->rel_error) << ", "
          << internal::FormatTime(best->TickCostUs()) << " per tick.\n";
    } else {
      out << "none of the settings.\n";
    }
  }
  return static_cast<bool>(out);
}

}  // namespace cosmems::bench
