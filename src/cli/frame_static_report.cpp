#include "frame_static_report.hpp"

#include <chrono>
#include <cmath>
#include <optional>

#include "comb_output.hpp"
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
  std::optional<FrameGapForce<ElectrostaticPressure>> electrostatic;
  if (IsOn(scene.effects.electrostatic)) {
    electrostatic.emplace(MakeFrameElectrostaticForce(model, MakeFramePullInOptions(scene),
                                                      *scene.effects.electrostatic->voltage));
  }
  FrameElementForce* ramped = electrostatic ? &*electrostatic : nullptr;
  if (!combs.empty()) {
    CombDriveSolution driven = SolveCombDrives(model, loads, combs, forces, ramped);
    solution = std::move(driven.statics);
    comb_states = std::move(driven.combs);
  } else if (ramped != nullptr || !forces.empty()) {
    solution = SolveFrameNonlinearStatic(model, forces, loads, ramped);
  } else {
    solution = SolveFrameStatic(model, loads);
  }
  if (electrostatic && solution.status == Status::kOk) {
    capacitance = electrostatic->Capacitance(solution.displacement);
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
  AddCombStates(structure_, combs_, comb_states_, json);
}

void FrameStaticReport::PrintResults(std::ostream& out) const {
  PrintFrameSolution(structure_, solution_, out);
  if (electrostatic_capacitance_f_) {
    out << "capacitance           " << Scientific(*electrostatic_capacitance_f_)
        << " F (the faces over the electrodes)\n";
  }
  PrintCombStates(structure_, combs_, comb_states_, out);
}

void FrameStaticReport::WriteFiles(const std::filesystem::path& directory) const {
  WriteFrameSolution(structure_, solution_, directory);
}

}  // namespace cosmems::internal
