#pragma once

#include <Eigen/Core>
#include <memory>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems::internal {

/// What a release analysis reports, in SI (doc/cli.md, release).
struct ReleaseResults {
  ContactSummary contact;  ///< after the release
  Eigen::MatrixXd shape;   ///< the equilibrium: one row per node, x (m), ux ... rz
};

/// The beam pressed onto the substrate all along and let go: every free node starts stuck, the
/// statics are solved with the scene's loads and forces, and the adhesion peels what it cannot
/// hold (SubstrateContact). stuck, detached_length_m, contact_length_m and release_shape.csv.
class ReleaseReport final : public AnalysisReport {
 public:
  ReleaseReport(RunHeader header, ReleaseResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  static std::unique_ptr<ReleaseReport> Run(const Scene& scene);

  const ReleaseResults& results() const { return results_; }

  /// release_shape.csv: x_m, ux_m, uy_m, uz_m, rx_rad, ry_rad, rz_rad of the equilibrium.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  ReleaseResults results_;
};

}  // namespace cosmems::internal
