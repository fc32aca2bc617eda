#include "pullin_report.hpp"

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
PullInReport::ControlPoint ControlOf(const FrameModel& model, int carrier) {
  PullInReport::ControlPoint out;
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

// A solved pull-in's results, and the header's warning when no fold lies below
// analysis.voltage_max.
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

}  // namespace

std::unique_ptr<PullInReport> PullInReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  Details details;
  details.structure = MakeStructureDescription(scene);
  const FrameModel model(details.structure, MakeFrameCouplings(scene));
  std::vector<CombDrive>& combs = details.combs = MakeCombDrives(scene, details.structure);
  FrameSceneForces others(model, scene);
  // The combs as the static analysis reports them with the electrodes at rest, and their side
  // instability.
  CombDriveSolution driven;
  if (!combs.empty()) driven = SolveCombDrives(model, FrameLoadCase{}, combs, others.elements());
  FramePullInResult& result = details.result;
  double gap = 0.0;
  details.electrodes = IsOn(scene.effects.electrostatic);
  if (details.electrodes) {
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
  details.control = ControlOf(model, result.control_carrier);
  details.comb_states = std::move(driven.combs);
  if (result.fold.status == Status::kOk) {
    details.stations = Stations(model, IsStraightBeam(scene));
    details.motions = details.stations.Motions(model, result.shape.displacement);
  }
  return std::make_unique<PullInReport>(std::move(header), std::move(results), std::move(details));
}

void PullInReport::AddResults(nlohmann::ordered_json& json) const {
  const Details& d = details_;
  json["pullin_voltage_v"] = results_.voltage_v;
  json["pullin_displacement_m"] = results_.displacement_m;
  json["pullin_travel_m"] = results_.travel_m;
  json["pullin_instability"] = ToString(results_.instability);
  json["solves"] = results_.solves;
  json["newton_iterations"] = results_.iterations;
  json["pullin_point"] = {
      {"name", d.control.name ? nlohmann::ordered_json(*d.control.name) : nlohmann::ordered_json()},
      {"position", ToJson(d.control.position)}};
  if (d.electrodes) json["capacitance_f"] = {{"electrostatic", d.result.capacitance_f}};
  AddCombStates(d.structure, d.combs, d.comb_states, json);
  AddFrameSolution(d.structure, d.result.shape, json);
}

void PullInReport::PrintResults(std::ostream& out) const {
  const Details& d = details_;
  if (d.electrodes) {
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
    out << "travel held at        " << d.control.name.value_or("a member's interior node") << " "
        << Vector(d.control.position) << " m\n";
    out << "capacitance at rest   " << Scientific(d.result.capacitance_f)
        << " F (the faces over the electrodes)\n";
  } else {
    out << "pull-in voltage       " << Significant(results_.voltage_v, 6)
        << " V (the combs' side instability, every comb's voltage scaled together)\n";
    out << "engagement at it      " << Scientific(results_.travel_m) << " m\n";
    out << "solves                " << results_.solves << "\n";
  }
  PrintCombStates(d.structure, d.combs, d.comb_states, out);
  out << "last stable state:\n";
  PrintFrameSolution(d.structure, d.result.shape, out);
}

void PullInReport::WriteFiles(const std::filesystem::path& directory) const {
  const Details& d = details_;
  d.stations.WriteMotions(directory, "pullin_shape.csv", d.motions);
  WriteFrameReactions(d.structure, d.result.shape.reactions, directory);
}

}  // namespace cosmems::internal
