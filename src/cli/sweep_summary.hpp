#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "sweep_condition.hpp"
#include "sweep_row.hpp"

namespace cosmems::internal {

/// What a sweep's rows say together (doc/sweeps.md): `samples`, `failed`, `yield` (the
/// fraction of all samples, failed ones included, that meet every condition; only with
/// conditions), `outputs` {FIELD: mean, std (n - 1), min, max, quantiles p01 ... p99
/// (linear between order statistics)} over the samples that ran, and `sensitivities`
/// {FIELD: {KEY: slope}}: the least-squares plane of each output over the numeric parameters
/// (with an intercept), given more samples than parameters and parameters that vary
/// independently. `wall_time_s` and `workers` are the caller's.
nlohmann::ordered_json SummarizeSweep(const std::vector<SweepRow>& rows,
                                      const std::vector<SweepCondition>& conditions);

}  // namespace cosmems::internal
