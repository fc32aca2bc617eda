#include "frame_static_report.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "frame_solution_output.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

std::unique_ptr<FrameStaticReport> FrameStaticReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  const FrameLoadCase loads = MakeFrameLoadCase(scene, structure);
  std::vector<CombDrive> combs = MakeCombDrives(scene, structure);
  std::vector<CombDriveState> comb_states;
  FrameStaticSolution solution;
  std::optional<double> capacitance;
  FrameSceneForces scene_forces(model, scene);
  const std::vector<FrameElementForce*>& forces = scene_forces.elements();
  if (IsOn(scene.effects.electrostatic)) {
    FrameGapForce<ElectrostaticPressure> electrostatic = MakeFrameElectrostaticForce(
        model, MakeFramePullInOptions(scene), *scene.effects.electrostatic->voltage);
    solution = SolveFrameNonlinearStatic(model, forces, loads, &electrostatic);
    if (solution.status == Status::kOk) {
      capacitance = electrostatic.Capacitance(solution.displacement);
    }
  } else if (!forces.empty()) {
    solution = SolveFrameNonlinearStatic(model, forces, loads);
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
  // Under a surface pressure every gap stays open in a solution (a closed one fails the solve).
  if (solution.status == Status::kOk && !scene.effects.HasSurfacePressure()) {
    header.WarnIfThroughSubstrate("the linear solution deflects", solution.max_deflection,
                                  scene.structure.gap);
  }
  // A supported device that finds no equilibrium under its surface forces has pulled in: its
  // tangent turned indefinite on the way, which is no fault of its supports.
  if (solution.status != Status::kOk && scene.effects.HasSurfacePressure() &&
      SpdSolver().Compute(model.Stiffness()) == Status::kOk) {
    header.status = Status::kNotConverged;
    header.warnings.push_back(
        IsOn(scene.effects.electrostatic)
            ? "no equilibrium up to effects.electrostatic.voltage: the device pulls in below it "
              "(run analysis.type = \"pullin\" for the voltage)"
            : "no equilibrium: the surface forces pull the device onto the substrate");
  }
  return std::make_unique<FrameStaticReport>(std::move(header), std::move(structure),
                                             std::move(solution), std::move(combs),
                                             std::move(comb_states), capacitance);
}

void FrameStaticReport::AddResults(nlohmann::ordered_json& json) const {
  AddFrameSolution(structure_, solution_, json);
  json["collapsed"] = false;
  if (electrostatic_capacitance_f_) {
    json["capacitance_f"] = {{"electrostatic", *electrostatic_capacitance_f_}};
  }
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
  PrintFrameSolution(structure_, solution_, out);
  if (electrostatic_capacitance_f_) {
    out << "capacitance           " << Scientific(*electrostatic_capacitance_f_)
        << " F (the faces over the electrodes)\n";
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
  WriteFrameSolution(structure_, solution_, directory);
}

}  // namespace cosmems::internal
