#pragma once

#include <memory>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "frame_contact_output.hpp"

namespace cosmems::internal {

/// What a device's release reports, in SI (doc/cli.md, release, devices).
struct FrameReleaseResults {
  FrameContactResults contact;             ///< the device's, each member's and each body's
  std::vector<FrameModel::Motion> nodes;   ///< (u [m], theta [rad]) of every node
  std::vector<FrameModel::Motion> bodies;  ///< of every body's centre
};

/// A device pressed onto the substrate all over and let go: every member node and every body
/// that can move starts stuck on the contact plane, the statics are solved with the scene's loads
/// and forces, and the adhesion releases what it cannot hold (FrameSubstrateContact). stuck,
/// shape, each member's and body's state, every node's and body's motion, and nodes.csv.
class FrameReleaseReport final : public AnalysisReport {
 public:
  FrameReleaseReport(RunHeader header, StructureDescription structure, FrameReleaseResults results)
      : AnalysisReport(std::move(header)),
        structure_(std::move(structure)),
        results_(std::move(results)) {}

  static std::unique_ptr<FrameReleaseReport> Run(const Scene& scene);

  const FrameReleaseResults& results() const { return results_; }

  /// nodes.csv: name, ux_m, uy_m, uz_m, rx_rad, ry_rad, rz_rad for every node and body.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  StructureDescription structure_;
  FrameReleaseResults results_;
};

}  // namespace cosmems::internal
