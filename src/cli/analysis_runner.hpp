#pragma once

#include <memory>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// Runs the analysis a validated scene declares, on its structure (a beam or a device), and
/// returns its report. A numerical failure is the report's status; invalid combinations that
/// only the analysis finds throw std::invalid_argument.
std::unique_ptr<AnalysisReport> RunAnalysis(const Scene& scene);

}  // namespace cosmems::internal
