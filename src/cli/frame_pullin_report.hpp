#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>

#include "analysis_report.hpp"
#include "cosmems/analysis/frame_pullin_analysis.hpp"
#include "cosmems/scene/scene.hpp"
#include "pullin_report.hpp"

namespace cosmems::internal {

/// A device's electrostatic pull-in over its electrodes (SolveFramePullIn): the fields of every
/// pull-in, the point whose travel was held, the capacitance at rest and the shape of the last
/// stable state as a static analysis reports it (doc/cli.md, pullin, devices).
class FramePullInReport final : public AnalysisReport {
 public:
  /// Where the travel was held: a node's or a body's name (none for a member's interior node).
  struct ControlPoint {
    std::optional<std::string> name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
  };

  FramePullInReport(RunHeader header, StructureDescription structure, PullInResults results,
                    FramePullInResult result, ControlPoint control)
      : AnalysisReport(std::move(header)),
        structure_(std::move(structure)),
        results_(std::move(results)),
        result_(std::move(result)),
        control_(std::move(control)) {}

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
};

}  // namespace cosmems::internal
