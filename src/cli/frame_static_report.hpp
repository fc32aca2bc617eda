#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/comb_drive_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/scene/scene.hpp"
#include "frame_contact_output.hpp"

namespace cosmems::internal {

/// A frame's statics: every node's and body's motion, the reactions at the anchors and the
/// members' largest deflection, stress and axial force; the capacitance of its electrodes, its
/// comb drives' forces, engagements, capacitances and side-instability voltages, and with contact
/// its state on the substrate, whether its surface forces collapsed it onto it (doc/cli.md,
/// static, frames).
class FrameStaticReport final : public AnalysisReport {
 public:
  FrameStaticReport(RunHeader header, StructureDescription structure, FrameStaticSolution solution,
                    std::vector<CombDrive> combs, std::vector<CombDriveState> comb_states,
                    std::optional<double> electrostatic_capacitance_f, bool collapsed,
                    FrameContactResults contact)
      : AnalysisReport(std::move(header)),
        structure_(std::move(structure)),
        solution_(std::move(solution)),
        combs_(std::move(combs)),
        comb_states_(std::move(comb_states)),
        electrostatic_capacitance_f_(electrostatic_capacitance_f),
        collapsed_(collapsed),
        contact_(std::move(contact)) {}

  static std::unique_ptr<FrameStaticReport> Run(const Scene& scene);

  const FrameStaticSolution& solution() const { return solution_; }

  /// nodes.csv: name, ux_m, uy_m, uz_m, rx_rad, ry_rad, rz_rad for every node and body;
  /// reactions.csv: node, fx_n, fy_n, fz_n, mx_nm, my_nm, mz_nm at every anchored node.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  StructureDescription structure_;
  FrameStaticSolution solution_;
  std::vector<CombDrive> combs_;
  std::vector<CombDriveState> comb_states_;  ///< one per comb when the solve succeeded
  /// F: the faces over the electrodes, in the solved state (with [effects.electrostatic]).
  std::optional<double> electrostatic_capacitance_f_;
  /// The surface forces folded before their full value: the device lies on the substrate (with
  /// contact) or has no equilibrium.
  bool collapsed_;
  FrameContactResults contact_;  ///< with contact or stiction, when the solve succeeded
};

}  // namespace cosmems::internal
