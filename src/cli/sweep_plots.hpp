#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "sweep_condition.hpp"
#include "sweep_row.hpp"

namespace cosmems::internal {

/// What a sweep's plots show: `fields`, each drawn against the sweep's keys (doc/sweeps.md) —
/// a curve over one numeric grid key, a map over two, a histogram when keys are drawn, with
/// the bound of each condition on that field as a line.
struct SweepPlotRequest {
  std::vector<std::string> fields;
  std::vector<std::string> grid_keys;  ///< the numeric grid keys, in the sweep's order
  bool random = false;                 ///< whether any key is drawn
  std::vector<SweepCondition> conditions;
};

/// The fields to plot when none is asked: each condition's field, else the first output after
/// the run's `wall_time_s` in the first sample that ran (the analysis's own first figure).
std::vector<std::string> DefaultPlotFields(const std::vector<SweepRow>& rows,
                                           const std::vector<SweepCondition>& conditions);

/// Writes, for each field, `plot_FIELD.dat` (the samples that ran), `plot_FIELD.gp` (the
/// gnuplot script) and, when gnuplot is on the PATH, `plot_FIELD.png` drawn by it; FIELD with
/// its brackets as underscores. Returns the PNG files written. A sweep of neither one or two
/// numeric grid keys nor drawn keys (three grid keys, a grid of strings) has no plot. Each file
/// appears whole or not at all (AtomicFile); OutputFileError when one cannot be written.
std::vector<std::filesystem::path> WriteSweepPlots(const std::filesystem::path& directory,
                                                   const std::vector<SweepRow>& rows,
                                                   const SweepPlotRequest& request);

}  // namespace cosmems::internal
