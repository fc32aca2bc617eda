#include "pullin_report.hpp"

#include <chrono>

#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "cosmems/scene/scene_forces.hpp"
#include "csv_file.hpp"
#include "nodal_shape.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

template <int Dim>
std::unique_ptr<PullInReport> RunPullIn(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  const BeamModel<Dim> model(MakeBeamDescription(scene));
  const PullInOptions options = MakePullInOptions(scene);
  // The forces besides the electrode's that the scene declares; only these are evaluated.
  SceneForces<Dim> others(model, scene);
  const PullInResult result = SolvePullIn(model, options, others.All());
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.status;
  header.dofs = model.FreeDofCount();

  PullInResults results;
  results.gap_m = options.electrode.gap;
  results.solves = result.solves;
  results.iterations = result.iterations;
  if (result.status == Status::kOk) {
    results.voltage_v = result.voltage_v;
    results.displacement_m = result.displacement_m;
    results.travel_m = result.travel_m;
    results.instability = result.instability;
    results.shape = WithNodePositions(model.NodeX(), model.units().length,
                                      BeamField<Dim>(model, result.displacement).AtNodes());
  } else if (scene.analysis.voltage_max && result.status == Status::kNotConverged) {
    header.warnings.push_back("no pull-in below analysis.voltage_max = " +
                              Significant(*scene.analysis.voltage_max) + " V");
  }
  return std::make_unique<PullInReport>(std::move(header), std::move(results));
}

}  // namespace

std::unique_ptr<PullInReport> PullInReport::Run(const Scene& scene) {
  return scene.model.dimension == 2 ? RunPullIn<2>(scene) : RunPullIn<3>(scene);
}

void PullInReport::AddResults(nlohmann::ordered_json& json) const {
  json["pullin_voltage_v"] = results_.voltage_v;
  json["pullin_displacement_m"] = results_.displacement_m;
  json["pullin_travel_m"] = results_.travel_m;
  json["pullin_instability"] = ToString(results_.instability);
  json["solves"] = results_.solves;
  json["newton_iterations"] = results_.iterations;
}

void PullInReport::PrintResults(std::ostream& out) const {
  out << "pull-in voltage       " << Significant(results_.voltage_v, 6) << " V\n";
  out << "travel at pull-in     " << Scientific(results_.travel_m) << " m ("
      << Significant(results_.travel_m / results_.gap_m, 4) << " of the gap)\n";
  out << "instability           "
      << (results_.instability == Instability::kLimitPoint
              ? "limit point (the voltage's largest value along the path)"
              : "bifurcation (the path's matrix turns singular while the voltage still rises)")
      << "\n";
  out << "last stable state     " << Scientific(results_.displacement_m)
      << " m largest deflection\n";
  out << "solves                " << results_.solves << " (" << results_.iterations
      << " Newton iterations)\n";
}

void PullInReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "pullin_shape.csv", "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  csv.Rows(results_.shape);
  csv.Close();
}

}  // namespace cosmems::internal
