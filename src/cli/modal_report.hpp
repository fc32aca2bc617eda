#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/mode_kind.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// One natural mode as the CLI reports it, in SI.
struct ModeResult {
  double frequency_hz = 0.0;
  ModeKind kind = ModeKind::kBendingY;
  /// One row per node: x (m), then ux, uy, uz, rx, ry, rz scaled so that the largest
  /// |translation| is 1 (for a torsion mode, which barely translates, the largest |rotation|).
  Eigen::MatrixXd shape;
};

/// Natural frequencies and modes: the JSON fields of doc/cli.md, modes.csv and mode_shapes.csv.
class ModalReport final : public AnalysisReport {
 public:
  ModalReport(RunHeader header, std::vector<ModeResult> modes)
      : AnalysisReport(std::move(header)), modes_(std::move(modes)) {}

  /// Builds the scene's model and solves for its analysis.count lowest modes.
  static std::unique_ptr<ModalReport> Run(const Scene& scene);

  const std::vector<ModeResult>& modes() const { return modes_; }

  /// modes.csv (mode, frequency_hz, kind) and mode_shapes.csv (mode, x_m, ux ... rz).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  std::vector<ModeResult> modes_;
};

}  // namespace cosmems::internal
