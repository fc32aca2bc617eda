#include "frame_pullin_report.hpp"

#include <chrono>

#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "frame_solution_output.hpp"
#include "json_vector.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

// The name of a carrier: its body's, or the description node's that it carries.
FramePullInReport::ControlPoint ControlOf(const FrameModel& model, int carrier) {
  FramePullInReport::ControlPoint out;
  if (carrier < 0) return out;
  const FrameMesh& mesh = model.mesh();
  const StructureDescription& s = model.description();
  out.position = mesh.carriers[carrier].position;
  const int body = mesh.carriers[carrier].body;
  if (body >= 0) {
    out.name = s.bodies[body].name;
    return out;
  }
  for (std::size_t n = 0; n < s.nodes.size(); ++n) {
    if (mesh.nodes[n].carrier == carrier) out.name = s.nodes[n].name;
  }
  return out;
}

}  // namespace

std::unique_ptr<FramePullInReport> FramePullInReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  const FramePullInOptions options = MakeFramePullInOptions(scene);
  FrameSceneForces others(model, scene);
  FramePullInResult result = SolveFramePullIn(model, options, others.elements());
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.fold.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();
  PullInResults results = ToPullInResults(result.fold, options.electrodes.gap, scene, header);
  ControlPoint control = ControlOf(model, result.control_carrier);
  return std::make_unique<FramePullInReport>(std::move(header), std::move(structure),
                                             std::move(results), std::move(result),
                                             std::move(control));
}

void FramePullInReport::AddResults(nlohmann::ordered_json& json) const {
  AddPullInFields(results_, json);
  json["pullin_point"] = {
      {"name", control_.name ? nlohmann::ordered_json(*control_.name) : nlohmann::ordered_json()},
      {"position", ToJson(control_.position)}};
  json["capacitance_f"] = {{"electrostatic", result_.capacitance_f}};
  AddFrameSolution(structure_, result_.shape, json);
}

void FramePullInReport::PrintResults(std::ostream& out) const {
  PrintPullInFields(results_, out);
  out << "travel held at        " << control_.name.value_or("a member's interior node") << " "
      << Vector(control_.position) << " m\n";
  out << "capacitance at rest   " << Scientific(result_.capacitance_f)
      << " F (the faces over the electrodes)\n";
  out << "last stable state:\n";
  PrintFrameSolution(structure_, result_.shape, out);
}

void FramePullInReport::WriteFiles(const std::filesystem::path& directory) const {
  WriteFrameSolution(structure_, result_.shape, directory);
}

}  // namespace cosmems::internal
