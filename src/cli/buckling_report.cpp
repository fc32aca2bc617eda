#include "buckling_report.hpp"

#include <chrono>

#include "cosmems/analysis/frame_buckling_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "csv_file.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

std::unique_ptr<BucklingReport> BucklingReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure);
  const bool beam = IsStraightBeam(scene);
  const FrameBucklingResult result =
      beam ? SolveMemberBuckling(model, 0)
           : SolveFrameBuckling(model, MakeFrameLoadCase(scene, structure));
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();
  const Stations stations(model, beam);
  BucklingResults results;
  if (result.status == Status::kOk) {
    Eigen::Index critical = 0;
    result.axial_force_n.minCoeff(&critical);
    const StructureMember& member = structure.members[model.mesh().elements[critical].member];
    results.load_factor = result.load_factor;
    results.critical_load_n = result.critical_load_n;
    results.critical_stress_pa = result.critical_load_n / member.section.Area();
    results.shape = stations.Shape(model, result.shape);
    if (-member.axial_load >= result.critical_load_n) {
      header.warnings.push_back("structure.axial_load = " + Significant(member.axial_load) +
                                " N already exceeds the critical compressive load: the straight "
                                "beam is unstable");
    }
  }
  if (!result.compressed && result.status != Status::kOk) {
    header.warnings.push_back("the loads compress no member: nothing buckles under them");
  }
  return std::make_unique<BucklingReport>(std::move(header), stations, std::move(results));
}

void BucklingReport::AddResults(nlohmann::ordered_json& json) const {
  json["critical_load_n"] = results_.critical_load_n;
  json["critical_stress_pa"] = results_.critical_stress_pa;
  json["load_factor"] = results_.load_factor;
}

void BucklingReport::PrintResults(std::ostream& out) const {
  out << "load factor           " << Significant(results_.load_factor, 6)
      << " (the buckling pattern times it buckles the structure)\n";
  out << "critical load         " << Scientific(results_.critical_load_n)
      << " N (the most compressed member's force then)\n";
  out << "critical stress       " << Scientific(results_.critical_stress_pa) << " Pa\n";
}

void BucklingReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "buckling_mode.csv", stations_.Key() + ",ux,uy,uz,rx,ry,rz");
  stations_.WriteRows(csv, results_.shape);
  csv.Close();
}

}  // namespace cosmems::internal
