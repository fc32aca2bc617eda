#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems::internal {

/// What a static solve reports, in SI (doc/cli.md, static).
struct StaticResults {
  std::optional<Eigen::Vector3d> tip_displacement;                 ///< m, cantilever only
  std::optional<Eigen::Vector3d> tip_rotation;                     ///< rad, cantilever only
  Eigen::Vector3d midspan_displacement = Eigen::Vector3d::Zero();  ///< m
  double max_deflection = 0.0;                                     ///< m toward the substrate
  double max_stress_pa = 0.0;
  double axial_force_n = 0.0;  ///< in the first element, tension > 0
  std::optional<double> gap;   ///< m, the scene's
  bool collapsed = false;      ///< no equilibrium short of the substrate (surface forces)
  std::optional<ContactSummary> contact;  ///< with contact declared
  Eigen::MatrixXd nodes;                  ///< one row per node: x, ux, uy, uz (m), rx, ry, rz (rad)
};

/// Linear statics: the JSON fields of doc/cli.md and deflection.csv.
class StaticReport final : public AnalysisReport {
 public:
  StaticReport(RunHeader header, StaticResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  /// Builds the scene's model, solves K u = f under its loads and recovers the fields.
  static std::unique_ptr<StaticReport> Run(const Scene& scene);

  const StaticResults& results() const { return results_; }

  /// deflection.csv: x_m, ux_m, uy_m, uz_m, rx_rad, ry_rad, rz_rad, one row per node.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  StaticResults results_;
};

}  // namespace cosmems::internal
