#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "frame_contact_output.hpp"
#include "stations.hpp"

namespace cosmems::internal {

/// What a release reports, in SI (doc/cli.md, release).
struct ReleaseResults {
  FrameContactResults contact;             ///< the structure's, each member's and each body's
  std::vector<FrameModel::Motion> nodes;   ///< (u [m], theta [rad]) of every node
  std::vector<FrameModel::Motion> bodies;  ///< of every body's centre
  Stations stations;                       ///< where the CSV lists the equilibrium
  Eigen::MatrixXd motions;  ///< one row per station: ux, uy, uz (m), rx, ry, rz (rad)
};

/// A structure pressed onto the substrate all over and let go: every member node and every body
/// that can move starts stuck on the contact plane, the statics are solved with the scene's loads
/// and forces, and the adhesion releases what it cannot hold (FrameSubstrateContact). stuck,
/// shape, the lengths (a structure of one member's), each member's and body's state, every
/// node's and body's motion, and the equilibrium along the beam or at every node.
class ReleaseReport final : public AnalysisReport {
 public:
  ReleaseReport(RunHeader header, StructureDescription structure, ReleaseResults results)
      : AnalysisReport(std::move(header)),
        structure_(std::move(structure)),
        results_(std::move(results)) {}

  static std::unique_ptr<ReleaseReport> Run(const Scene& scene);

  const ReleaseResults& results() const { return results_; }

  /// release_shape.csv (x_m, along a beam) or nodes.csv (name, at every node and body): ux_m,
  /// uy_m, uz_m, rx_rad, ry_rad, rz_rad of the equilibrium.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  StructureDescription structure_;
  ReleaseResults results_;
};

}  // namespace cosmems::internal
