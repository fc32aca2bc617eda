#include "static_report.hpp"

#include <chrono>

#include "contact_report.hpp"
#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/static_analysis.hpp"
#include "cosmems/rod/rod_field.hpp"
#include "cosmems/rod/rod_load_case.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "cosmems/scene/scene_forces.hpp"
#include "csv_file.hpp"
#include "json_vector.hpp"
#include "nodal_shape.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

// The statics of the scene's forces: the loads and the surface pressures ramped together from
// the unloaded beam. A ramp that stops short of its full value met a fold: no equilibrium is left
// short of the substrate, the beam has collapsed; with contact, the equilibrium lying on the
// substrate is then solved for from the beam pressed down all along (`resting` says whether it
// was found; if not, the last stable state is returned).
template <int Dim>
NonlinearStaticSolution SolveWithForces(const BeamModel<Dim>& model, SceneForces<Dim>& forces,
                                        const LoadCase& loads, bool& collapsed, bool& resting) {
  ForceSum* pressures = forces.pressures().Empty() ? nullptr : &forces.pressures();
  NonlinearStaticSolution out =
      SolveNonlinearStatic(model, forces.structural(), loads, {}, pressures);
  collapsed = pressures && out.status != Status::kOk;
  resting = false;
  if (!collapsed || !forces.contact()) return out;
  NonlinearStaticOptions pressed;
  pressed.start = forces.contact()->PressedDisplacement();
  NonlinearStaticSolution down = SolveNonlinearStatic(model, *forces.All(), loads, pressed);
  resting = down.status == Status::kOk;
  return resting ? down : out;
}

template <int Dim>
std::unique_ptr<StaticReport> RunStatic(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const LoadCase loads = MakeLoadCase(scene);
  const auto start = std::chrono::steady_clock::now();
  const BeamModel<Dim> model(MakeBeamDescription(scene));
  SceneForces<Dim> forces(model, scene);
  StaticSolution solution;
  StaticResults results;
  double load_factor = 1.0;
  bool resting = false;
  if (forces.Empty()) {
    solution = SolveStatic(model, loads);
  } else {
    const NonlinearStaticSolution nonlinear =
        SolveWithForces(model, forces, loads, results.collapsed, resting);
    solution.status = nonlinear.status;
    solution.displacement = nonlinear.displacement;
    load_factor = nonlinear.load_factor;
    // Collapsed and not resting on the substrate: the last stable state is reported.
    if (results.collapsed && !resting) solution.status = Status::kOk;
  }
  // N - N0 of a stretching beam, uniform along it (internal units).
  const double stretched =
      forces.stretching() && solution.status == Status::kOk
          ? forces.stretching()->AxialForce(solution.displacement) - model.AxialLoad()
          : 0.0;
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = solution.status;
  header.dofs = model.FreeDofCount();

  results.gap = scene.structure.gap;
  if (forces.contact() && (!results.collapsed || resting)) {
    results.contact = forces.contact()->Summary();
  }
  if (solution.status != Status::kOk) {
    return std::make_unique<StaticReport>(std::move(header), std::move(results));
  }
  if (results.collapsed && !resting) {
    header.warnings.push_back(
        "collapsed: no equilibrium short of the substrate beyond " +
        Significant(100.0 * load_factor, 4) +
        " % of the loads and surface forces; the fields are those of the last stable state " +
        (forces.contact() ? "(Newton from the beam pressed onto the substrate did not find it "
                            "resting there)"
                          : "(declare [effects.contact] for the beam lying on the substrate)"));
  }
  const BeamField<Dim> field(model, solution.displacement);
  const double length = scene.structure.length;
  if (scene.structure.kind == StructureKind::kCantilever) {
    const typename BeamField<Dim>::Vector6 tip = field.At(length);
    results.tip_displacement = tip.template head<3>();
    results.tip_rotation = tip.template tail<3>();
  }
  results.midspan_displacement = field.At(0.5 * length).template head<3>();
  results.max_deflection = field.MaxDeflectionTowardSubstrate();
  const double stretched_n = stretched * model.units().force;
  results.max_stress_pa = field.MaxStress(stretched_n);
  results.axial_force_n = field.AxialForce(0) + stretched_n;
  results.nodes = WithNodePositions(model.NodeX(), model.units().length, field.AtNodes());
  if (!forces.contact()) {
    header.WarnIfThroughSubstrate(
        forces.Empty() ? "the linear solution deflects" : "the solution deflects",
        results.max_deflection, results.gap);
  }
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
  results.nodes = WithNodePositions(rod.NodeX(), rod.units().length, field.AtNodes());
  header.WarnIfThroughSubstrate("the solution deflects", results.max_deflection, results.gap);
  return std::make_unique<StaticReport>(std::move(header), std::move(results));
}

}  // namespace

std::unique_ptr<StaticReport> StaticReport::Run(const Scene& scene) {
  if (scene.model.theory == Theory::kCosserat) return RunCosseratStatic(scene);
  return scene.model.dimension == 2 ? RunStatic<2>(scene) : RunStatic<3>(scene);
}

void StaticReport::AddResults(nlohmann::ordered_json& json) const {
  if (results_.tip_displacement) json["tip_displacement"] = ToJson(*results_.tip_displacement);
  json["midspan_displacement"] = ToJson(results_.midspan_displacement);
  if (results_.tip_rotation) json["tip_rotation"] = ToJson(*results_.tip_rotation);
  json["max_deflection"] = results_.max_deflection;
  json["max_stress_pa"] = results_.max_stress_pa;
  json["axial_force_n"] = results_.axial_force_n;
  json["collapsed"] = results_.collapsed;
  if (results_.contact) json["contact"] = ContactJson(*results_.contact);
}

void StaticReport::PrintResults(std::ostream& out) const {
  if (results_.tip_displacement) {
    out << "tip deflection        " << Scientific(results_.tip_displacement->y()) << " m\n";
    out << "tip displacement      " << Vector(*results_.tip_displacement) << " m\n";
    out << "tip rotation          " << Vector(*results_.tip_rotation) << " rad\n";
  }
  out << "midspan displacement  " << Vector(results_.midspan_displacement) << " m\n";
  out << "max deflection        " << Scientific(results_.max_deflection)
      << " m toward the substrate";
  if (results_.gap) out << " (gap " << Significant(*results_.gap) << " m)";
  out << "\n";
  out << "max stress            " << Scientific(results_.max_stress_pa) << " Pa\n";
  out << "axial force           " << Scientific(results_.axial_force_n) << " N\n";
  if (results_.collapsed) out << "collapsed             snapped onto the substrate\n";
  if (results_.contact) PrintContact(out, *results_.contact);
}

void StaticReport::WriteFiles(const std::filesystem::path& directory) const {
  CsvFile csv(directory / "deflection.csv", "x_m,ux_m,uy_m,uz_m,rx_rad,ry_rad,rz_rad");
  csv.Rows(results_.nodes);
  csv.Close();
}

}  // namespace cosmems::internal
