#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/comb_drive_analysis.hpp"
#include "cosmems/analysis/fold_search.hpp"
#include "cosmems/analysis/frame_pullin_analysis.hpp"
#include "cosmems/scene/scene.hpp"
#include "stations.hpp"

namespace cosmems::internal {

/// What every pull-in analysis reports, in SI (doc/cli.md, pullin).
struct PullInResults {
  double voltage_v = 0.0;       ///< the pull-in voltage
  double displacement_m = 0.0;  ///< largest deflection of the last stable state
  double travel_m = 0.0;        ///< the held point's travel at pull-in
  double gap_m = 0.0;
  Instability instability = Instability::kLimitPoint;  ///< how the stable path ended
  int solves = 0;
  int iterations = 0;
};

/// The pull-in of any structure on its netlist: over its electrodes (SolveFramePullIn, its comb
/// drives held at their voltages), or without electrodes its comb drives' side instability
/// (SolveCombDrives). The fields of every pull-in, the point whose travel was held, the
/// electrodes' capacitance at rest, the combs as a static analysis reports them with the
/// electrodes at rest, and the last stable state as a static analysis reports it (doc/cli.md,
/// pullin).
class PullInReport final : public AnalysisReport {
 public:
  /// Where the travel was held: a node's or a body's name (none for a member's interior node).
  struct ControlPoint {
    std::optional<std::string> name;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m
  };

  /// What the analysis found besides the fields of every pull-in.
  struct Details {
    StructureDescription structure;
    FramePullInResult result;
    ControlPoint control;
    bool electrodes = false;  ///< the electrodes' fold; otherwise the combs' side instability
    std::vector<CombDrive> combs;
    std::vector<CombDriveState> comb_states;  ///< at their voltages, the electrodes at rest
    Stations stations;                        ///< where the CSV lists the last stable state
    Eigen::MatrixXd motions;  ///< one row per station: ux, uy, uz (m), rx, ry, rz (rad)
  };

  PullInReport(RunHeader header, PullInResults results, Details details)
      : AnalysisReport(std::move(header)),
        results_(std::move(results)),
        details_(std::move(details)) {}

  static std::unique_ptr<PullInReport> Run(const Scene& scene);

  const PullInResults& results() const { return results_; }
  const FramePullInResult& result() const { return details_.result; }

  /// The last stable state: pullin_shape.csv (x_m, along a beam) or nodes.csv (name, at every
  /// node and body) with ux_m ... rz_rad, and reactions.csv (as a static analysis writes them).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  PullInResults results_;
  Details details_;
};

}  // namespace cosmems::internal
