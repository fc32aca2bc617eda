#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/mode_kind.hpp"
#include "cosmems/scene/scene.hpp"
#include "stations.hpp"

namespace cosmems::internal {

/// One natural mode as the CLI reports it, in SI.
struct ModeResult {
  double frequency_hz = 0.0;
  ModeKind kind = ModeKind::kBendingY;
  std::array<double, 6> participation{};  ///< effective mass fractions: ux, uy, uz, rx, ry, rz
  /// One row per station: ux, uy, uz, rx, ry, rz scaled so that the largest |translation| is 1
  /// (the largest |rotation| for a mode that barely translates).
  Eigen::MatrixXd shape;
};

/// Natural frequencies and modes with their participations: the JSON fields of doc/cli.md,
/// modes.csv and mode_shapes.csv.
class ModalReport final : public AnalysisReport {
 public:
  ModalReport(RunHeader header, Stations stations, std::vector<ModeResult> modes)
      : AnalysisReport(std::move(header)),
        stations_(std::move(stations)),
        modes_(std::move(modes)) {}

  /// Builds the scene's structure and solves for its analysis.count lowest modes (about its
  /// loaded equilibrium when its members stretch).
  static std::unique_ptr<ModalReport> Run(const Scene& scene);

  const std::vector<ModeResult>& modes() const { return modes_; }

  /// modes.csv (mode, frequency_hz, kind, the six participations) and mode_shapes.csv (mode, the
  /// station: x_m along a beam or a name, ux ... rz).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  Stations stations_;
  std::vector<ModeResult> modes_;
};

}  // namespace cosmems::internal
