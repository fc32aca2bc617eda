#pragma once

// A console reporter that also keeps, for every benchmark of the accuracy-versus-time report, one
// AccuracyCostRow: its median times over the repetitions and its error counter.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>
#include <vector>

#include "accuracy_cost_table.hpp"

namespace cosmems::bench {

/// Prints what Google Benchmark's console reporter prints and collects the rows. A benchmark is
/// named "problem/..." and labelled with its SettingsLabel; it reports the counter `rel_error`
/// and, when the timed call is a time step, `steps_per_tick` (steps per 1 ms of simulated time).
class AccuracyCostReporter : public benchmark::ConsoleReporter {
 public:
  AccuracyCostReporter() : benchmark::ConsoleReporter(OO_Tabular) {}

  bool ReportContext(const Context& context) override {
    cpus_ = context.cpu_info.num_cpus;
    mhz_ = context.cpu_info.cycles_per_second * 1e-6;
    return benchmark::ConsoleReporter::ReportContext(context);
  }

  /// `runs` holds one benchmark's repetitions and, with more than one, their aggregates; the
  /// row takes the "median" aggregate when there is one, else the median of the repetitions.
  void ReportRuns(const std::vector<Run>& runs) override {
    benchmark::ConsoleReporter::ReportRuns(runs);
    if (runs.empty() || runs.front().report_big_o || runs.front().report_rms) return;
    const Run* median = nullptr;
    std::vector<const Run*> repetitions;
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") median = &run;
      if (run.run_type == Run::RT_Iteration) repetitions.push_back(&run);
    }
    if (!median && repetitions.empty()) return;
    const Run& source = median ? *median : *repetitions.front();
    AccuracyCostRow row;
    const std::string& name = source.run_name.function_name;
    row.problem = name.substr(0, name.find('/'));
    row.settings = ParseSettings(source.report_label);
    row.repetitions =
        median ? static_cast<int>(source.repetitions) : static_cast<int>(repetitions.size());
    row.failed = source.error_occurred;
    row.message = source.error_message;
    if (!row.failed) {
      row.rel_error = Counter(source, "rel_error");
      row.calls_per_tick =
          source.counters.count("steps_per_tick") ? Counter(source, "steps_per_tick") : 1.0;
      row.time_us = median ? CpuMicroSeconds(*median) : Median(repetitions, CpuMicroSeconds);
      row.real_time_us = median ? RealMicroSeconds(*median) : Median(repetitions, RealMicroSeconds);
    }
    rows_.push_back(row);
  }

  const std::vector<AccuracyCostRow>& rows() const { return rows_; }
  /// "N CPUs at F MHz", from the context of the run.
  std::string Machine() const {
    return std::to_string(cpus_) + " CPUs at " + std::to_string(static_cast<long>(mhz_)) + " MHz";
  }

 private:
  static double Counter(const Run& run, const char* name) {
    const auto it = run.counters.find(name);
    return it == run.counters.end() ? 0.0 : it->second.value;
  }

  static double CpuMicroSeconds(const Run& run) {
    return run.GetAdjustedCPUTime() * 1e6 / benchmark::GetTimeUnitMultiplier(run.time_unit);
  }

  static double RealMicroSeconds(const Run& run) {
    return run.GetAdjustedRealTime() * 1e6 / benchmark::GetTimeUnitMultiplier(run.time_unit);
  }

  static double Median(const std::vector<const Run*>& runs, double (*time)(const Run&)) {
    std::vector<double> us;
    us.reserve(runs.size());
    for (const Run* run : runs) us.push_back(time(*run));
    std::sort(us.begin(), us.end());
    const std::size_t n = us.size();
    return n % 2 ? us[n / 2] : 0.5 * (us[n / 2 - 1] + us[n / 2]);
  }

  std::vector<AccuracyCostRow> rows_;
  int cpus_ = 0;
  double mhz_ = 0.0;
};

}  // namespace cosmems::bench
