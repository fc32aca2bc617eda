#pragma once

#include <Eigen/Core>
#include <memory>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// What a buckling analysis reports, in SI (doc/cli.md, buckling).
struct BucklingResults {
  double critical_load_n = 0.0;  ///< compressive axial force of the first buckling mode
  /// N/m^2: critical_load_n over the section's area, the residual stress that buckles the beam
  double critical_stress_pa = 0.0;
  Eigen::MatrixXd shape;  ///< one row per node: x (m), then ux ... rz scaled to max |u| = 1
};

/// Linear buckling (K_L - mu G_0) x = 0: critical_load_n and buckling_mode.csv.
class BucklingReport final : public AnalysisReport {
 public:
  BucklingReport(RunHeader header, BucklingResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  static std::unique_ptr<BucklingReport> Run(const Scene& scene);

  const BucklingResults& results() const { return results_; }

  /// buckling_mode.csv: x_m, ux, uy, uz, rx, ry, rz of the first mode, largest |u| = 1.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  BucklingResults results_;
};

}  // namespace cosmems::internal
