#include "release_report.hpp"

#include <algorithm>
#include <chrono>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "frame_solution_output.hpp"
#include "json_vector.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

std::unique_ptr<ReleaseReport> ReleaseReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  const FrameLoadCase loads = MakeFrameLoadCase(scene, structure);
  FrameSceneForces scene_forces(model, scene);
  FrameSubstrateContact& contact = *scene_forces.contact();
  ForceSum forces;  // the statics' forces: the film, a velocity's, has no share
  for (FrameElementForce* force : scene_forces.elements()) forces.Add(*force);
  forces.Add(contact);
  contact.StickAll();
  NonlinearStaticOptions options;
  options.start = contact.PressedDisplacement();
  // One node or plate lets go per settle: room for every one of them, and the multipliers'.
  options.newton.max_settles =
      std::max(options.newton.max_settles, 4 * static_cast<int>(contact.points().points().size()));
  NonlinearStaticSolve solve(model.Stiffness(), forces, options, scene_forces.electrodes());
  const NonlinearStaticSolution solution = solve.Solve(AssembleFrameLoads(model, loads));
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = solution.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();

  ReleaseResults results;
  if (solution.status == Status::kOk) {
    results.contact = FrameContactResults::Of(contact, structure);
    FrameStaticSolution motions;
    motions.displacement = solution.displacement;
    RecoverFrameMotions(model, motions);
    results.nodes = std::move(motions.nodes);
    results.bodies = std::move(motions.bodies);
    results.stations = Stations(model, IsStraightBeam(scene));
    results.motions = results.stations.Motions(model, solution.displacement);
  }
  return std::make_unique<ReleaseReport>(std::move(header), std::move(structure),
                                         std::move(results));
}

void ReleaseReport::AddResults(nlohmann::ordered_json& json) const {
  const ContactSummary& c = results_.contact.contact;
  json["stuck"] = c.Stuck();
  json["shape"] = ToString(c.shape);
  if (results_.contact.has_lengths) {
    json["detached_length_m"] = c.detached_length_m;
    json["contact_length_m"] = c.contact_length_m;
  } else {
    json["detached_length_m"] = nullptr;
    json["contact_length_m"] = nullptr;
  }
  nlohmann::ordered_json nodes = nlohmann::ordered_json::object();
  for (std::size_t n = 0; n < results_.nodes.size(); ++n) {
    nodes[structure_.nodes[n].name] = MotionJson(results_.nodes[n]);
  }
  json["nodes"] = nodes;
  nlohmann::ordered_json bodies = nlohmann::ordered_json::object();
  for (std::size_t b = 0; b < results_.bodies.size(); ++b) {
    bodies[structure_.bodies[b].name] = MotionJson(results_.bodies[b]);
  }
  json["bodies"] = bodies;
  if (results_.contact.declared) AddFrameContact(structure_, results_.contact, json);
}

void ReleaseReport::PrintResults(std::ostream& out) const {
  out << "after release         " << Describe(results_.contact.contact.shape) << "\n";
  if (results_.contact.declared) PrintFrameContact(structure_, results_.contact, out);
}

void ReleaseReport::WriteFiles(const std::filesystem::path& directory) const {
  results_.stations.WriteMotions(directory, "release_shape.csv", results_.motions);
}

}  // namespace cosmems::internal
