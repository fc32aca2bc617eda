#include "frame_static_report.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include "comb_output.hpp"
#include "cosmems/analysis/frame_pullin_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "frame_solution_output.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

// A device whose surface forces fold before their full value has no equilibrium short of the
// substrate: the one lying on it, every force at its full value (the electrodes' too). Newton
// from the device pressed down all over flips the points its springs lift between held and clear
// at every iteration and does not converge (measured on a plate on four beams, even with no
// force but the contact); so the device is first released from there with no adhesion to hold it
// (every point stuck, then let go edge by edge where it pulls, as the release analysis peels),
// and the scene's contact is solved from that state, every point a hair (twice the tolerance)
// lower so that the contact holds those lying on the plane from the first iteration: released,
// they sit within the tolerance above it, and without them the electrodes' negative stiffness
// leaves the Newton matrix indefinite.
FrameStaticSolution SolveResting(const Scene& scene, const FrameModel& model,
                                 const FrameLoadCase& loads, std::vector<FrameElementForce*> forces,
                                 FrameElementForce* electrodes, FrameSubstrateContact& contact) {
  ContactOptions letting_go = MakeContactOptions(scene);
  letting_go.stiction = true;
  letting_go.adhesion_energy = std::numeric_limits<double>::min();
  FrameSubstrateContact release(model, letting_go);
  release.StickAll();
  NonlinearStaticOptions options;
  options.start = release.PressedDisplacement();
  // One point or plate lets go per settle: room for every one of them, and the multipliers'.
  options.newton.max_settles =
      std::max(options.newton.max_settles, 4 * static_cast<int>(release.points().points().size()));
  if (electrodes != nullptr) forces.push_back(electrodes);
  std::vector<FrameElementForce*> released = forces;
  std::replace(released.begin(), released.end(), static_cast<FrameElementForce*>(&contact),
               static_cast<FrameElementForce*>(&release));
  const FrameStaticSolution lying =
      SolveFrameNonlinearStatic(model, released, loads, nullptr, options);
  if (lying.status != Status::kOk) return lying;
  options.start = lying.displacement;
  const double below = 2.0 * contact.tolerance() / model.units().length;
  for (int c = 0; c < static_cast<int>(model.mesh().carriers.size()); ++c) {
    const int uy = model.CarrierDof(c, 1);
    if (uy >= 0) options.start[uy] -= below;
  }
  contact.Reset();
  return SolveFrameNonlinearStatic(model, forces, loads, nullptr, options);
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
  bool collapsed = false;
  std::optional<double> capacitance;
  FrameSceneForces scene_forces(model, scene);
  FrameSubstrateContact* contact = scene_forces.contact();
  std::vector<FrameElementForce*> forces = scene_forces.elements();
  if (contact) forces.push_back(contact);
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
    collapsed = scene.effects.HasSurfacePressure() && solution.status != Status::kOk;
    if (collapsed && contact) {
      solution = SolveResting(scene, model, loads, forces, ramped, *contact);
    }
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
  if (solution.status == Status::kOk && !scene.effects.HasSurfacePressure() && !contact) {
    header.WarnIfThroughSubstrate("the linear solution deflects", solution.max_deflection,
                                  scene.structure.gap);
  }
  // A supported device that finds no equilibrium under its surface forces has pulled in: its
  // tangent turned indefinite on the way, which is no fault of its supports.
  FrameContactResults contact_results;
  if (contact && solution.status == Status::kOk) {
    contact_results = FrameContactResults::Of(*contact, structure);
  }
  if (solution.status != Status::kOk && scene.effects.HasSurfacePressure() &&
      SpdSolver().Compute(model.Stiffness()) == Status::kOk) {
    header.status = Status::kNotConverged;
    header.warnings.push_back(
        IsOn(scene.effects.electrostatic)
            ? "no equilibrium up to effects.electrostatic.voltage: the device pulls in below it "
              "(run analysis.type = \"pullin\" for the voltage)"
            : "no equilibrium: the surface forces pull the device onto the substrate");
    if (!contact) {
      header.warnings.push_back("declare [effects.contact] for the device lying on the substrate");
    }
  }
  return std::make_unique<FrameStaticReport>(
      std::move(header), std::move(structure), std::move(solution), std::move(combs),
      std::move(comb_states), capacitance, collapsed, std::move(contact_results));
}

void FrameStaticReport::AddResults(nlohmann::ordered_json& json) const {
  AddFrameSolution(structure_, solution_, json);
  json["collapsed"] = collapsed_;
  if (contact_.declared) AddFrameContact(structure_, contact_, json);
  if (electrostatic_capacitance_f_) {
    json["capacitance_f"] = {{"electrostatic", *electrostatic_capacitance_f_}};
  }
  AddCombStates(structure_, combs_, comb_states_, json);
}

void FrameStaticReport::PrintResults(std::ostream& out) const {
  PrintFrameSolution(structure_, solution_, out);
  if (collapsed_) out << "collapsed             snapped onto the substrate\n";
  if (contact_.declared) PrintFrameContact(structure_, contact_, out);
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
