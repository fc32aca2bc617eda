#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/comb_drive_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/scene/scene.hpp"
#include "frame_contact_output.hpp"
#include "stations.hpp"

namespace cosmems::internal {

/// What a static solve reports, in SI (doc/cli.md, static).
struct StaticResults {
  std::optional<Eigen::Vector3d> tip_displacement;      ///< m, a cantilever's
  std::optional<Eigen::Vector3d> tip_rotation;          ///< rad, a cantilever's
  std::optional<Eigen::Vector3d> midspan_displacement;  ///< m, a straight beam's
  double max_deflection = 0.0;                          ///< m toward the substrate
  double max_stress_pa = 0.0;
  double axial_force_n = 0.0;  ///< tension > 0
  std::optional<double> gap;   ///< m, the scene's
  /// The surface forces folded before their full value: the structure lies on the substrate
  /// (with contact) or has no equilibrium.
  bool collapsed = false;
  /// The netlist and its solution's nodes, bodies and reactions (a frame's, not the rod's).
  std::optional<StructureDescription> structure;
  FrameStaticSolution solution;
  FrameContactResults contact;  ///< with contact or stiction, when the solve succeeded
  /// F: the faces over the electrodes, in the solved state (with [effects.electrostatic]).
  std::optional<double> electrostatic_capacitance_f;
  std::vector<CombDrive> combs;
  std::vector<CombDriveState> comb_states;  ///< one per comb when the solve succeeded
  Stations stations;                        ///< where the CSV lists the motions
  Eigen::MatrixXd motions;  ///< one row per station: ux, uy, uz (m), rx, ry, rz (rad)
};

/// Statics of any structure, a beam's or a device's, on its netlist (the Cosserat rod on its
/// own model): the JSON fields of doc/cli.md and the motions along the beam or at every node.
class StaticReport final : public AnalysisReport {
 public:
  StaticReport(RunHeader header, StaticResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  /// Builds the scene's model and forces, solves its statics under its loads and recovers the
  /// fields.
  static std::unique_ptr<StaticReport> Run(const Scene& scene);

  const StaticResults& results() const { return results_; }

  /// deflection.csv (x_m, along a beam) or nodes.csv (name, at every node and body): ux_m, uy_m,
  /// uz_m, rx_rad, ry_rad, rz_rad; reactions.csv: node, fx_n, fy_n, fz_n, mx_nm, my_nm, mz_nm at
  /// every anchored node (a frame's).
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  StaticResults results_;
};

}  // namespace cosmems::internal
