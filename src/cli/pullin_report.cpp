#include "pullin_report.hpp"

#include <chrono>

#include "cosmems/analysis/beam_field.hpp"
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

  PullInResults results = ToPullInResults(result, options.electrode.gap, scene, header);
  if (result.status == Status::kOk) {
    results.shape = WithNodePositions(model.NodeX(), model.units().length,
                                      BeamField<Dim>(model, result.displacement).AtNodes());
  }
  return std::make_unique<PullInReport>(std::move(header), std::move(results));
}

}  // namespace

std::unique_ptr<PullInReport> PullInReport::Run(const Scene& scene) {
  return scene.model.dimension == 2 ? RunPullIn<2>(scene) : RunPullIn<3>(scene);
}

PullInResults ToPullInResults(const PullInResult& result, double gap_m, const Scene& scene,
                              RunHeader& header) {
  PullInResults out;
  out.gap_m = gap_m;
  out.solves = result.solves;
  out.iterations = result.iterations;
  if (result.status == Status::kOk) {
    out.voltage_v = result.voltage_v;
    out.displacement_m = result.displacement_m;
    out.travel_m = result.travel_m;
    out.instability = result.instability;
  } else if (scene.analysis.voltage_max && result.status == Status::kNotConverged) {
    header.warnings.push_back("no pull-in below analysis.voltage_max = " +
                              Significant(*scene.analysis.voltage_max) + " V");
  }
  return out;
}

void AddPullInFields(const PullInResults& results, nlohmann::ordered_json& json) {
  json["pullin_voltage_v"] = results.voltage_v;
  json["pullin_displacement_m"] = results.displacement_m;
  json["pullin_travel_m"] = results.travel_m;
  json["pullin_instability"] = ToString(results.instability);
  json["solves"] = results.solves;
  json["newton_iterations"] = results.iterations;
}

void PrintPullInFields(const PullInResults& results, std::ostream& out) {
  out << "pull-in voltage       " << Significant(results.voltage_v, 6) << " V\n";
  out << "travel at pull-in     " << Scientific(results.travel_m) << " m ("
      << Significant(results.travel_m / results.gap_m, 4) << " of the gap)\n";
  out << "instability           "
      << (results.instability == Instability::kLimitPoint
              ? "limit point (the voltage's largest value along the path)"
              : "bifurcation (the path's matrix turns singular while the voltage still rises)")
      << "\n";
  out << "last stable state     " << Scientific(results.displacement_m)
      << " m largest deflection\n";
  out << "solves                " << results.solves << " (" << results.iterations
      << " Newton iterations)\n";
}

void PullInReport::AddResults(nlohmann::ordered_json& json) const {
  AddPullInFields(results_, json);
}

void PullInReport::PrintResults(std::ostream& out) const { PrintPullInFields(results_, out); }

void PullInReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "pullin_shape.csv", "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  csv.Rows(results_.shape);
  csv.Close();
}

}  // namespace cosmems::internal
