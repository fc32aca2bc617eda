#include "frame_static_report.hpp"

#include <chrono>
#include <cmath>

#include "cosmems/scene/frame_conversion.hpp"
#include "csv_file.hpp"
#include "json_vector.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

nlohmann::ordered_json MotionJson(const FrameModel::Motion& m) {
  return {{"displacement", ToJson(m.head<3>())}, {"rotation", ToJson(m.tail<3>())}};
}

}  // namespace

std::unique_ptr<FrameStaticReport> FrameStaticReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  const FrameLoadCase loads = MakeFrameLoadCase(scene, structure);
  std::vector<CombDrive> combs = MakeCombDrives(scene, structure);
  std::vector<CombDriveState> comb_states;
  FrameStaticSolution solution;
  if (scene.model.theory == Theory::kStretching) {
    FrameStretchingForce force(model);
    solution = SolveFrameNonlinearStatic(model, force, loads);
  } else if (!combs.empty()) {
    CombDriveSolution driven = SolveCombDrives(model, loads, combs);
    solution = std::move(driven.statics);
    comb_states = std::move(driven.combs);
  } else {
    solution = SolveFrameStatic(model, loads);
  }
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = solution.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();
  if (solution.status == Status::kOk) {
    header.WarnIfThroughSubstrate("the linear solution deflects", solution.max_deflection,
                                  scene.structure.gap);
  }
  return std::make_unique<FrameStaticReport>(std::move(header), std::move(structure),
                                             std::move(solution), std::move(combs),
                                             std::move(comb_states));
}

void FrameStaticReport::AddResults(nlohmann::ordered_json& json) const {
  nlohmann::ordered_json nodes = nlohmann::ordered_json::object();
  for (std::size_t n = 0; n < structure_.nodes.size(); ++n) {
    nodes[structure_.nodes[n].name] = MotionJson(solution_.nodes[n]);
  }
  nlohmann::ordered_json bodies = nlohmann::ordered_json::object();
  for (std::size_t b = 0; b < structure_.bodies.size(); ++b) {
    bodies[structure_.bodies[b].name] = MotionJson(solution_.bodies[b]);
  }
  nlohmann::ordered_json reactions = nlohmann::ordered_json::object();
  for (const FrameReaction& r : solution_.reactions) {
    reactions[structure_.nodes[r.node].name] = {{"force", ToJson(r.force)},
                                                {"moment", ToJson(r.moment)}};
  }
  json["max_deflection"] = solution_.max_deflection;
  json["max_stress_pa"] = solution_.max_stress_pa;
  json["axial_force_n"] = solution_.axial_force_n;
  json["collapsed"] = false;
  json["nodes"] = nodes;
  json["bodies"] = bodies;
  json["reactions"] = reactions;
  if (comb_states_.empty()) return;
  nlohmann::ordered_json capacitances = nlohmann::ordered_json::array();
  nlohmann::ordered_json side = nlohmann::ordered_json::array();
  nlohmann::ordered_json combs = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < comb_states_.size(); ++c) {
    const CombDriveState& state = comb_states_[c];
    capacitances.push_back(state.capacitance_f);
    // null: no voltage up to a million times the scene's reaches it.
    side.push_back(std::isfinite(state.side_instability_voltage_v)
                       ? nlohmann::ordered_json(state.side_instability_voltage_v)
                       : nlohmann::ordered_json());
    combs.push_back({{"body", structure_.bodies[combs_[c].body].name},
                     {"force_n", state.force_n},
                     {"engagement_m", state.engagement_m}});
  }
  json["capacitance_f"] = {{"combs", capacitances}};
  json["side_instability_voltage_v"] = side;
  json["combs"] = combs;
}

void FrameStaticReport::PrintResults(std::ostream& out) const {
  out << "max deflection        " << Scientific(solution_.max_deflection)
      << " m toward the substrate\n";
  out << "max stress            " << Scientific(solution_.max_stress_pa) << " Pa\n";
  out << "axial force           " << Scientific(solution_.axial_force_n)
      << " N (the largest in a member)\n";
  for (std::size_t n = 0; n < structure_.nodes.size(); ++n) {
    out << "node " << structure_.nodes[n].name << "  " << Vector(solution_.nodes[n].head<3>())
        << " m\n";
  }
  for (std::size_t b = 0; b < structure_.bodies.size(); ++b) {
    out << "body " << structure_.bodies[b].name << "  " << Vector(solution_.bodies[b].head<3>())
        << " m, " << Vector(solution_.bodies[b].tail<3>()) << " rad\n";
  }
  for (const FrameReaction& r : solution_.reactions) {
    out << "reaction " << structure_.nodes[r.node].name << "  " << Vector(r.force) << " N, "
        << Vector(r.moment) << " N m\n";
  }
  for (std::size_t c = 0; c < comb_states_.size(); ++c) {
    const CombDriveState& state = comb_states_[c];
    out << "comb " << c << " on " << structure_.bodies[combs_[c].body].name << "  force "
        << Scientific(state.force_n) << " N, engaged " << Scientific(state.engagement_m) << " m, "
        << Scientific(state.capacitance_f) << " F, side instability at ";
    if (std::isfinite(state.side_instability_voltage_v)) {
      out << Significant(state.side_instability_voltage_v, 4) << " V\n";
    } else {
      out << "no voltage up to 1e6 times the scene's\n";
    }
  }
}

void FrameStaticReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile motions(directory / "nodes.csv", "name,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  auto row = [&](const std::string& name, const FrameModel::Motion& m) {
    std::vector<std::string> cells = {name};
    for (int k = 0; k < 6; ++k) cells.push_back(CsvFile::Number(m[k]));
    motions.Row(cells);
  };
  for (std::size_t n = 0; n < structure_.nodes.size(); ++n) {
    row(structure_.nodes[n].name, solution_.nodes[n]);
  }
  for (std::size_t b = 0; b < structure_.bodies.size(); ++b) {
    row(structure_.bodies[b].name, solution_.bodies[b]);
  }
  motions.Close();
  CsvFile reactions(directory / "reactions.csv", "node,fx_n,fy_n,fz_n,mx_nm,my_nm,mz_nm");
  for (const FrameReaction& r : solution_.reactions) {
    std::vector<std::string> cells = {structure_.nodes[r.node].name};
    for (int k = 0; k < 3; ++k) cells.push_back(CsvFile::Number(r.force[k]));
    for (int k = 0; k < 3; ++k) cells.push_back(CsvFile::Number(r.moment[k]));
    reactions.Row(cells);
  }
  reactions.Close();
}

}  // namespace cosmems::internal
