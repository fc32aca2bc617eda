#include "frame_pullin_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

#include "comb_output.hpp"
#include "cosmems/analysis/comb_drive_force.hpp"
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

// The combs' side instability as the pull-in of a device without electrodes: every comb's
// voltage scaled together, the voltage the highest of them reaches, the last stable state's
// shape, and the largest engagement there as the travel.
FramePullInResult CombPullIn(const FrameModel& model, const CombDriveSolution& driven,
                             const std::vector<CombDrive>& combs) {
  FramePullInResult out;
  out.fold.status = driven.statics.status;
  out.fold.solves = driven.solves;
  if (out.fold.status != Status::kOk) return out;
  if (!std::isfinite(driven.side_instability_factor)) {
    out.fold.status = Status::kNotConverged;
    return out;
  }
  out.fold.instability = Instability::kBifurcation;
  out.shape = driven.last_stable;
  out.fold.displacement = out.shape.displacement;
  out.fold.displacement_m = out.shape.max_deflection;
  for (std::size_t c = 0; c < combs.size(); ++c) {
    out.fold.voltage_v = std::max(out.fold.voltage_v, driven.combs[c].side_instability_voltage_v);
    const double engaged = out.shape.bodies[combs[c].body].head<3>().dot(combs[c].Axis());
    if (std::abs(engaged) > std::abs(out.fold.travel_m)) out.fold.travel_m = engaged;
  }
  out.control_carrier = model.mesh().body_carrier[combs.front().body];
  return out;
}

}  // namespace

std::unique_ptr<FramePullInReport> FramePullInReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  std::vector<CombDrive> combs = MakeCombDrives(scene, structure);
  FrameSceneForces others(model, scene);
  // The combs as the static analysis reports them with the electrodes at rest, and their side
  // instability.
  CombDriveSolution driven;
  if (!combs.empty()) driven = SolveCombDrives(model, FrameLoadCase{}, combs, others.elements());
  FramePullInResult result;
  double gap = 0.0;
  const bool electrodes = IsOn(scene.effects.electrostatic);
  if (electrodes) {
    // The electrodes' fold with the combs held at their voltages.
    const FramePullInOptions options = MakeFramePullInOptions(scene);
    std::vector<FrameElementForce*> forces = others.elements();
    std::optional<CombDriveForce> held;
    if (!combs.empty()) forces.push_back(&held.emplace(model, combs));
    result = SolveFramePullIn(model, options, forces);
    gap = options.electrodes.gap;
  } else {
    result = CombPullIn(model, driven, combs);
    gap = combs.front().gap;
    const std::optional<double>& most = scene.analysis.voltage_max;
    if (result.fold.status == Status::kOk && most && result.fold.voltage_v > *most) {
      result = FramePullInResult{};  // ToPullInResults says why
      result.fold.status = Status::kNotConverged;
    } else if (result.fold.status == Status::kNotConverged && !most) {
      header.warnings.push_back(
          "no side instability up to 1e6 times the combs' voltages: the suspension holds them");
    }
  }
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.fold.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();
  PullInResults results = ToPullInResults(result.fold, gap, scene, header);
  ControlPoint control = ControlOf(model, result.control_carrier);
  return std::make_unique<FramePullInReport>(
      std::move(header), std::move(structure), std::move(results), std::move(result),
      std::move(control), electrodes, std::move(combs), std::move(driven.combs));
}

void FramePullInReport::AddResults(nlohmann::ordered_json& json) const {
  AddPullInFields(results_, json);
  json["pullin_point"] = {
      {"name", control_.name ? nlohmann::ordered_json(*control_.name) : nlohmann::ordered_json()},
      {"position", ToJson(control_.position)}};
  if (electrodes_) json["capacitance_f"] = {{"electrostatic", result_.capacitance_f}};
  AddCombStates(structure_, combs_, comb_states_, json);
  AddFrameSolution(structure_, result_.shape, json);
}

void FramePullInReport::PrintResults(std::ostream& out) const {
  if (electrodes_) {
    PrintPullInFields(results_, out);
    out << "travel held at        " << control_.name.value_or("a member's interior node") << " "
        << Vector(control_.position) << " m\n";
    out << "capacitance at rest   " << Scientific(result_.capacitance_f)
        << " F (the faces over the electrodes)\n";
  } else {
    out << "pull-in voltage       " << Significant(results_.voltage_v, 6)
        << " V (the combs' side instability, every comb's voltage scaled together)\n";
    out << "engagement at it      " << Scientific(results_.travel_m) << " m\n";
    out << "solves                " << results_.solves << "\n";
  }
  PrintCombStates(structure_, combs_, comb_states_, out);
  out << "last stable state:\n";
  PrintFrameSolution(structure_, result_.shape, out);
}

void FramePullInReport::WriteFiles(const std::filesystem::path& directory) const {
  WriteFrameSolution(structure_, result_.shape, directory);
}

}  // namespace cosmems::internal
