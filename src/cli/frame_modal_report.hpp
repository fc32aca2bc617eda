#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/mode_kind.hpp"
#include "cosmems/scene/scene.hpp"

namespace cosmems::internal {

/// One mode of a frame as the CLI reports it, in SI.
struct FrameModeResult {
  double frequency_hz = 0.0;
  ModeKind kind = ModeKind::kBendingY;
  std::array<double, 6> participation{};  ///< effective mass fractions: ux, uy, uz, rx, ry, rz
  /// One row per node, then per body (names()): ux, uy, uz, rx, ry, rz, scaled so that the
  /// largest |translation| is 1 (the largest |rotation| for a mode that barely translates).
  Eigen::MatrixXd shape;
};

/// A frame's modes with their participations (doc/cli.md, modal, frames).
class FrameModalReport final : public AnalysisReport {
 public:
  FrameModalReport(RunHeader header, std::vector<std::string> names,
                   std::vector<FrameModeResult> modes)
      : AnalysisReport(std::move(header)), names_(std::move(names)), modes_(std::move(modes)) {}

  static std::unique_ptr<FrameModalReport> Run(const Scene& scene);

  const std::vector<FrameModeResult>& modes() const { return modes_; }

  /// modes.csv (mode, frequency_hz, kind, the six participations) and mode_shapes.csv (mode,
  /// name, ux ... rz at every node and body).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  std::vector<std::string> names_;  ///< the nodes', then the bodies'
  std::vector<FrameModeResult> modes_;
};

}  // namespace cosmems::internal
