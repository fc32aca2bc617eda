#pragma once

#include <Eigen/Core>
#include <memory>

#include "analysis_report.hpp"
#include "cosmems/analysis/fold_search.hpp"
#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// What a pull-in analysis reports, in SI (doc/cli.md, pullin).
struct PullInResults {
  double voltage_v = 0.0;       ///< the pull-in voltage
  double displacement_m = 0.0;  ///< largest deflection of the last stable state
  double travel_m = 0.0;        ///< deflection at the tip (midspan) at pull-in
  double gap_m = 0.0;
  Instability instability = Instability::kLimitPoint;  ///< how the stable path ended
  int solves = 0;
  int iterations = 0;
  Eigen::MatrixXd shape;  ///< the last stable state: one row per node, x (m), ux ... rz
};

/// A solved pull-in's results (all but the shape), and the header's warning when no fold lies
/// below analysis.voltage_max.
PullInResults ToPullInResults(const PullInResult& result, double gap_m, const Scene& scene,
                              RunHeader& header);

/// pullin_voltage_v, pullin_displacement_m, pullin_travel_m, pullin_instability, solves and
/// newton_iterations: what every pull-in reports.
void AddPullInFields(const PullInResults& results, nlohmann::ordered_json& json);
/// The same as text.
void PrintPullInFields(const PullInResults& results, std::ostream& out);

/// Electrostatic pull-in by displacement control (SolvePullIn) with the scene's theory and
/// surface forces: pullin_voltage_v, pullin_displacement_m and pullin_shape.csv.
class PullInReport final : public AnalysisReport {
 public:
  PullInReport(RunHeader header, PullInResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  static std::unique_ptr<PullInReport> Run(const Scene& scene);

  const PullInResults& results() const { return results_; }

  /// pullin_shape.csv: x_m, ux_m, uy_m, uz_m, rx_rad, ry_rad, rz_rad of the last stable state.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  PullInResults results_;
};

}  // namespace cosmems::internal
