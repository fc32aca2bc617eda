#include "release_report.hpp"

#include <chrono>

#include "contact_report.hpp"
#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "cosmems/scene/scene_forces.hpp"
#include "csv_file.hpp"
#include "nodal_shape.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

template <int Dim>
std::unique_ptr<ReleaseReport> RunRelease(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  const BeamModel<Dim> model(MakeBeamDescription(scene));
  SceneForces<Dim> forces(model, scene);
  SubstrateContact<Dim>& contact = *forces.contact();
  contact.StickAll();
  NonlinearStaticOptions options;
  options.start = contact.PressedDisplacement();
  const NonlinearStaticSolution solution =
      SolveNonlinearStatic(model, *forces.All(), MakeLoadCase(scene), options);
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = solution.status;
  header.dofs = model.FreeDofCount();

  ReleaseResults results;
  if (solution.status == Status::kOk) {
    results.contact = contact.Summary();
    results.shape = WithNodePositions(model.NodeX(), model.units().length,
                                      BeamField<Dim>(model, solution.displacement).AtNodes());
  }
  return std::make_unique<ReleaseReport>(std::move(header), std::move(results));
}

}  // namespace

std::unique_ptr<ReleaseReport> ReleaseReport::Run(const Scene& scene) {
  return scene.model.dimension == 2 ? RunRelease<2>(scene) : RunRelease<3>(scene);
}

void ReleaseReport::AddResults(nlohmann::ordered_json& json) const {
  const ContactSummary& c = results_.contact;
  json["stuck"] = c.Stuck();
  json["shape"] = ToString(c.shape);
  json["detached_length_m"] = c.detached_length_m;
  json["contact_length_m"] = c.contact_length_m;
  json["contact"] = ContactJson(c);
}

void ReleaseReport::PrintResults(std::ostream& out) const {
  out << "after release         " << Describe(results_.contact.shape) << "\n";
  PrintContact(out, results_.contact);
}

void ReleaseReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "release_shape.csv", "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  csv.Rows(results_.shape);
  csv.Close();
}

}  // namespace cosmems::internal
