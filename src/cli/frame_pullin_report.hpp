#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/comb_drive_analysis.hpp"
#include "cosmems/analysis/frame_pullin_analysis.hpp"
#include "cosmems/scene/scene.hpp"
#include "pullin_report.hpp"

namespace cosmems::internal {

/// A device's pull-in: over its electrodes (SolveFramePullIn, its comb drives held at their
/// voltages), or without electrodes its comb drives' side instability (SolveCombDrives). The
/// fields of every pull-in, the point whose travel was held (the first comb's body), the
/// electrodes' capacitance at rest, the combs as a static analysis reports them with the
/// electrodes at rest, and the shape of the last stable state (doc/cli.md, pullin, devices).
class FramePullInReport final : public AnalysisReport {
 public:
  /// Where the travel was held: a node's or a body's name (none for a member's interior node).
  struct ControlPoint {
    std::optional<std::string> name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
  };

  /// `electrodes`: the pull-in is the electrodes' fold; otherwise the combs' side instability.
  FramePullInReport(RunHeader header, StructureDescription structure, PullInResults results,
                    FramePullInResult result, ControlPoint control, bool electrodes,
                    std::vector<CombDrive> combs, std::vector<CombDriveState> comb_states)
      : AnalysisReport(std::move(header)),
        structure_(std::move(structure)),
        results_(std::move(results)),
        result_(std::move(result)),
        control_(std::move(control)),
        electrodes_(electrodes),
        combs_(std::move(combs)),
        comb_states_(std::move(comb_states)) {}

  static std::unique_ptr<FramePullInReport> Run(const Scene& scene);

  const FramePullInResult& result() const { return result_; }

  /// nodes.csv and reactions.csv of the last stable state (as a static analysis writes them).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  StructureDescription structure_;
  PullInResults results_;
  FramePullInResult result_;
  ControlPoint control_;
  bool electrodes_;
  std::vector<CombDrive> combs_;
  std::vector<CombDriveState> comb_states_;  ///< at their voltages, the electrodes at rest
};

}  // namespace cosmems::internal
