#include "buckling_report.hpp"

#include <chrono>

#include "cosmems/analysis/buckling_analysis.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "csv_file.hpp"
#include "nodal_shape.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

template <int Dim>
std::unique_ptr<BucklingReport> RunBuckling(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  const BeamModel<Dim> model(MakeBeamDescription(scene));
  const BucklingResult result = SolveBuckling(model);
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.status;
  header.dofs = model.FreeDofCount();

  BucklingResults results;
  if (result.status == Status::kOk) {
    const BucklingMode& first = result.modes.at(0);
    results.critical_load_n = first.critical_load_n;
    results.critical_stress_pa =
        first.critical_load_n / (scene.structure.width * scene.structure.thickness);
    results.shape = NodalShape(model, first.shape, false);
    if (-scene.structure.axial_load >= first.critical_load_n) {
      header.warnings.push_back(
          "structure.axial_load = " + Significant(scene.structure.axial_load) +
          " N already exceeds the critical compressive load: the straight "
          "beam is unstable");
    }
  }
  return std::make_unique<BucklingReport>(std::move(header), std::move(results));
}

}  // namespace

std::unique_ptr<BucklingReport> BucklingReport::Run(const Scene& scene) {
  return scene.model.dimension == 2 ? RunBuckling<2>(scene) : RunBuckling<3>(scene);
}

void BucklingReport::AddResults(nlohmann::ordered_json& json) const {
  json["critical_load_n"] = results_.critical_load_n;
  json["critical_stress_pa"] = results_.critical_stress_pa;
}

void BucklingReport::PrintResults(std::ostream& out) const {
  out << "critical load         " << Scientific(results_.critical_load_n) << " N (compressive)\n";
  out << "critical stress       " << Scientific(results_.critical_stress_pa) << " Pa\n";
}

void BucklingReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "buckling_mode.csv", "x_m,ux,uy,uz,rx,ry,rz");
  csv.Rows(results_.shape);
  csv.Close();
}

}  // namespace cosmems::internal
