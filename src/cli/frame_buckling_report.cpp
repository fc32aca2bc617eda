#include "frame_buckling_report.hpp"

#include <chrono>

#include "cosmems/analysis/frame_buckling_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "csv_file.hpp"
#include "frame_shape.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

std::unique_ptr<FrameBucklingReport> FrameBucklingReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure);
  const FrameBucklingResult result = SolveFrameBuckling(model, MakeFrameLoadCase(scene, structure));
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();
  std::vector<std::string> names;
  for (const StructureNode& node : structure.nodes) names.push_back(node.name);
  for (const StructureBody& body : structure.bodies) names.push_back(body.name);
  Eigen::MatrixXd shape;
  if (result.status == Status::kOk) shape = FrameShape(model, result.shape);
  if (!result.compressed && result.status != Status::kOk) {
    header.warnings.push_back("the loads compress no member: nothing buckles under them");
  }
  return std::make_unique<FrameBucklingReport>(std::move(header), result.load_factor,
                                               result.critical_load_n, std::move(names),
                                               std::move(shape));
}

void FrameBucklingReport::AddResults(nlohmann::ordered_json& json) const {
  json["critical_load_n"] = critical_load_n_;
  json["load_factor"] = load_factor_;
}

void FrameBucklingReport::PrintResults(std::ostream& out) const {
  out << "load factor           " << Significant(load_factor_, 6)
      << " (the loads times it buckle the device)\n";
  out << "critical load         " << Scientific(critical_load_n_)
      << " N (the most compressed member's force then)\n";
}

void FrameBucklingReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "buckling_mode.csv", "name,ux,uy,uz,rx,ry,rz");
  for (std::size_t n = 0; n < names_.size(); ++n) {
    std::vector<std::string> cells = {names_[n]};
    for (int k = 0; k < 6; ++k) cells.push_back(CsvFile::Number(shape_(n, k)));
    csv.Row(cells);
  }
  csv.Close();
}

}  // namespace cosmems::internal
