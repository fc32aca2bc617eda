#include "static_report.hpp"

#include <algorithm>
#include <chrono>
#include <limits>

#include "comb_output.hpp"
#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/rod/rod_field.hpp"
#include "cosmems/rod/rod_load_case.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "frame_solution_output.hpp"
#include "json_vector.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

// A structure whose surface forces fold before their full value has no equilibrium short of the
// substrate: the one lying on it, every force at its full value (the pressures too). Newton from
// the structure pressed down all over flips the points its springs lift between held and clear
// at every iteration and does not converge (measured on a plate on four beams, even with no
// force but the contact); so it is first released from there with no adhesion to hold it (every
// point stuck, then let go edge by edge where it pulls, as the release analysis peels), and the
// scene's contact is solved from that state, every point a hair (twice the tolerance) lower so
// that the contact holds those lying on the plane from the first iteration: released, they sit
// within the tolerance above it, and without them the electrodes' negative stiffness leaves the
// Newton matrix indefinite.
FrameStaticSolution SolveResting(const Scene& scene, const FrameModel& model,
                                 const FrameLoadCase& loads, std::vector<FrameElementForce*> forces,
                                 const std::vector<FrameElementForce*>& pressures,
                                 FrameSubstrateContact& contact) {
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
  forces.insert(forces.end(), pressures.begin(), pressures.end());
  std::vector<FrameElementForce*> released = forces;
  std::replace(released.begin(), released.end(), static_cast<FrameElementForce*>(&contact),
               static_cast<FrameElementForce*>(&release));
  const FrameStaticSolution lying = SolveFrameNonlinearStatic(model, released, loads, {}, options);
  if (lying.status != Status::kOk) return lying;
  options.start = lying.displacement;
  const double below = 2.0 * contact.tolerance() / model.units().length;
  for (int c = 0; c < static_cast<int>(model.mesh().carriers.size()); ++c) {
    const int uy = model.CarrierDof(c, 1);
    if (uy >= 0) options.start[uy] -= below;
  }
  contact.Reset();
  return SolveFrameNonlinearStatic(model, forces, loads, {}, options);
}

// A straight beam's points of interest: the tip (a cantilever's) and the midspan.
void AddBeamPoints(const Scene& scene, const FrameModel& model, const Eigen::VectorXd& d,
                   StaticResults& results) {
  const auto at = [&](double x) {
    FrameModel::Motion m = model.MemberMotion(d, 0, x);
    m.head<3>() *= model.units().length;
    return m;
  };
  if (scene.structure.kind == StructureKind::kCantilever) {
    const FrameModel::Motion tip = at(1.0);
    results.tip_displacement = tip.head<3>();
    results.tip_rotation = tip.tail<3>();
  }
  results.midspan_displacement = at(0.5).head<3>();
}

// The statics of the scene's netlist: the loads ramped together with every pressure across the
// gap (the electrodes', Casimir's, van der Waals'), from the unloaded structure held by its
// members' stretching; with comb drives, their side instability too (SolveCombDrives). A ramp
// that stops short of its full value met a fold: the structure has collapsed, and with contact
// the equilibrium lying on the substrate is solved for (SolveResting).
std::unique_ptr<StaticReport> RunFrameStatic(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  StaticResults results;
  results.gap = scene.structure.gap;
  StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  const FrameLoadCase loads = MakeFrameLoadCase(scene, structure);
  results.combs = MakeCombDrives(scene, structure);
  FrameSceneForces scene_forces(model, scene);
  FrameSubstrateContact* contact = scene_forces.contact();
  std::vector<FrameElementForce*> forces = scene_forces.held();
  if (contact) forces.push_back(contact);
  std::vector<FrameElementForce*> pressures = scene_forces.pressures();
  if (FrameGapForce<ElectrostaticPressure>* electrodes = scene_forces.electrodes()) {
    pressures.insert(pressures.begin(), electrodes);
  }
  FrameStaticSolution& solution = results.solution;
  if (!results.combs.empty()) {
    CombDriveSolution driven = SolveCombDrives(model, loads, results.combs, forces, pressures);
    solution = std::move(driven.statics);
    results.comb_states = std::move(driven.combs);
  } else if (!pressures.empty() || !forces.empty()) {
    solution = SolveFrameNonlinearStatic(model, forces, loads, pressures);
    results.collapsed = !pressures.empty() && solution.status != Status::kOk;
    if (results.collapsed && contact) {
      solution = SolveResting(scene, model, loads, forces, pressures, *contact);
    }
  } else {
    solution = SolveFrameStatic(model, loads);
  }
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = solution.status;
  header.dofs = model.FreeDofCount();
  header.model.elements = model.ElementCount();
  if (solution.status == Status::kOk) {
    if (const FrameGapForce<ElectrostaticPressure>* electrodes = scene_forces.electrodes()) {
      results.electrostatic_capacitance_f = electrodes->Capacitance(solution.displacement);
    }
    if (contact) results.contact = FrameContactResults::Of(*contact, structure);
    if (IsStraightBeam(scene)) AddBeamPoints(scene, model, solution.displacement, results);
    results.max_deflection = solution.max_deflection;
    results.max_stress_pa = solution.max_stress_pa;
    results.axial_force_n = solution.axial_force_n;
    results.stations = Stations(model, IsStraightBeam(scene));
    results.motions = results.stations.Motions(model, solution.displacement);
    // Under a surface pressure every gap stays open in a solution (a closed one fails the solve).
    if (pressures.empty() && !contact) {
      header.WarnIfThroughSubstrate("the linear solution deflects", solution.max_deflection,
                                    scene.structure.gap);
    }
  } else if (!pressures.empty() && SpdSolver().Compute(model.Stiffness()) == Status::kOk) {
    // A supported structure that finds no equilibrium under its surface forces has pulled in:
    // its tangent turned indefinite on the way, which is no fault of its supports.
    header.status = Status::kNotConverged;
    header.warnings.push_back(
        IsOn(scene.effects.electrostatic)
            ? "no equilibrium up to effects.electrostatic.voltage: the structure pulls in below "
              "it (run analysis.type = \"pullin\" for the voltage)"
            : "no equilibrium: the surface forces pull the structure onto the substrate");
    if (!contact) {
      header.warnings.push_back(
          "declare [effects.contact] for the structure lying on the substrate");
    }
  }
  results.structure = std::move(structure);
  return std::make_unique<StaticReport>(std::move(header), std::move(results));
}

// Large deflections: the Cosserat rod's equilibrium, reached from the straight rod by Newton with
// adaptive load steps.
std::unique_ptr<StaticReport> RunCosseratStatic(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const LoadCase loads = MakeLoadCase(scene);
  const auto start = std::chrono::steady_clock::now();
  const CosseratRod rod(MakeBeamDescription(scene));
  CosseratStaticSolver solver(rod);
  header.status = solver.Solve(RodLoadsFor(rod, loads));
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.dofs = rod.FreeDofCount();

  StaticResults results;
  results.gap = scene.structure.gap;
  if (header.status != Status::kOk) {
    return std::make_unique<StaticReport>(std::move(header), std::move(results));
  }
  const RodState& state = solver.state();
  const RodField field(rod, state);
  if (scene.structure.kind == StructureKind::kCantilever) {
    results.tip_displacement = rod.TipDisplacement(state);
    results.tip_rotation = rod.TipRotation(state);
  }
  results.midspan_displacement = rod.DisplacementAt(state, 0.5 * scene.structure.length);
  results.max_deflection = field.MaxDeflectionTowardSubstrate();
  results.max_stress_pa = field.MaxStress();
  Eigen::Vector3d force, moment;
  rod.ElementResultants(state, 0, force, moment);
  results.axial_force_n = force.x();
  results.stations = Stations::AlongAxis(rod.NodeX(), rod.units().length);
  results.motions = field.AtNodes();
  header.WarnIfThroughSubstrate("the solution deflects", results.max_deflection, results.gap);
  return std::make_unique<StaticReport>(std::move(header), std::move(results));
}

}  // namespace

std::unique_ptr<StaticReport> StaticReport::Run(const Scene& scene) {
  return scene.model.theory == Theory::kCosserat ? RunCosseratStatic(scene) : RunFrameStatic(scene);
}

void StaticReport::AddResults(nlohmann::ordered_json& json) const {
  const StaticResults& r = results_;
  if (r.tip_displacement) json["tip_displacement"] = ToJson(*r.tip_displacement);
  if (r.midspan_displacement) json["midspan_displacement"] = ToJson(*r.midspan_displacement);
  if (r.tip_rotation) json["tip_rotation"] = ToJson(*r.tip_rotation);
  json["max_deflection"] = r.max_deflection;
  json["max_stress_pa"] = r.max_stress_pa;
  json["axial_force_n"] = r.axial_force_n;
  if (r.structure) AddFrameMotions(*r.structure, r.solution, json);
  json["collapsed"] = r.collapsed;
  if (r.contact.declared) AddFrameContact(*r.structure, r.contact, json);
  if (r.electrostatic_capacitance_f) {
    json["capacitance_f"] = {{"electrostatic", *r.electrostatic_capacitance_f}};
  }
  if (r.structure) AddCombStates(*r.structure, r.combs, r.comb_states, json);
}

void StaticReport::PrintResults(std::ostream& out) const {
  const StaticResults& r = results_;
  if (r.tip_displacement) {
    out << "tip deflection        " << Scientific(r.tip_displacement->y()) << " m\n";
    out << "tip displacement      " << Vector(*r.tip_displacement) << " m\n";
    out << "tip rotation          " << Vector(*r.tip_rotation) << " rad\n";
  }
  if (r.midspan_displacement) {
    out << "midspan displacement  " << Vector(*r.midspan_displacement) << " m\n";
  }
  out << "max deflection        " << Scientific(r.max_deflection) << " m toward the substrate";
  if (r.gap) out << " (gap " << Significant(*r.gap) << " m)";
  out << "\n";
  out << "max stress            " << Scientific(r.max_stress_pa) << " Pa\n";
  out << "axial force           " << Scientific(r.axial_force_n) << " N\n";
  if (r.structure) PrintFrameMotions(*r.structure, r.solution, out);
  if (r.collapsed) out << "collapsed             snapped onto the substrate\n";
  if (r.contact.declared) PrintFrameContact(*r.structure, r.contact, out);
  if (r.electrostatic_capacitance_f) {
    out << "capacitance           " << Scientific(*r.electrostatic_capacitance_f)
        << " F (the faces over the electrodes)\n";
  }
  if (r.structure) PrintCombStates(*r.structure, r.combs, r.comb_states, out);
}

void StaticReport::WriteFiles(const std::filesystem::path& directory) const {
  const StaticResults& r = results_;
  r.stations.WriteMotions(directory, "deflection.csv", r.motions);
  if (r.structure) WriteFrameReactions(*r.structure, r.solution.reactions, directory);
}

}  // namespace cosmems::internal
