#pragma once

#include <Eigen/Core>
#include <memory>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"
#include "stations.hpp"

namespace cosmems::internal {

/// What a buckling analysis reports, in SI (doc/cli.md, buckling).
struct BucklingResults {
  /// The factor on the buckling pattern: a device's loads, a beam's unit end compression (1 N).
  double load_factor = 0.0;
  double critical_load_n = 0.0;  ///< the most compressed member's axial force at buckling
  /// N/m^2: critical_load_n over that member's section: the residual stress that buckles a beam
  double critical_stress_pa = 0.0;
  Eigen::MatrixXd shape;  ///< one row per station: ux ... rz scaled to max |u| = 1
};

/// Linear buckling: a beam's under an axial compression (Euler's load), a device's under its
/// loads; critical_load_n, load_factor, critical_stress_pa and buckling_mode.csv.
class BucklingReport final : public AnalysisReport {
 public:
  BucklingReport(RunHeader header, Stations stations, BucklingResults results)
      : AnalysisReport(std::move(header)),
        stations_(std::move(stations)),
        results_(std::move(results)) {}

  static std::unique_ptr<BucklingReport> Run(const Scene& scene);

  const BucklingResults& results() const { return results_; }

  /// buckling_mode.csv: the station (x_m along a beam, or a name), ux, uy, uz, rx, ry, rz of the
  /// first mode, largest |u| = 1.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  Stations stations_;
  BucklingResults results_;
};

}  // namespace cosmems::internal
