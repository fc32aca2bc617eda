#include "transient_report.hpp"

#include <algorithm>
#include <chrono>
#include <string>

#include "contact_report.hpp"
#include "cosmems/analysis/comb_drive_analysis.hpp"
#include "cosmems/analysis/cosserat_transient_analysis.hpp"
#include "cosmems/analysis/frame_transient_analysis.hpp"
#include "cosmems/rod/rod_load_case.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "cosmems/scene/scene_conversion.hpp"
#include "csv_file.hpp"
#include "frame_contact_output.hpp"
#include "text_format.hpp"

namespace cosmems::internal {
namespace {

// Times are multiples of the time step and carry its rounding (3 * 1e-6 = 3.0000000000000004e-6);
// twelve digits tell apart every step of the longest run the scene allows (1e8 steps).
constexpr int kTimeDigits = 12;

// Where uy is recorded, as JSON keys and CSV headers name it.
const char* OutputPointName(StructureKind kind) {
  return kind == StructureKind::kCantilever ? "tip" : "midspan";
}

constexpr const char* kAxes[3] = {"x", "y", "z"};

// Runs the scene's netlist; `results` takes the recorded points and their history, and the
// contact's state and events when it has contact. A beam watches its deflection u_y.
TransientResult RunFrame(const Scene& scene, const TransientOptions& options, int& dofs,
                         TransientResults& results) {
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  dofs = model.FreeDofCount();
  const std::vector<FrameRecordPoint> record = MakeFrameRecord(scene, structure);
  // The nonlinear forces the scene declares (only these are evaluated) and what its voltages
  // drive: the combs' forces as loads, the electrodes' pressure scaled by V(t)^2.
  FrameSceneForces scene_forces(model, scene);
  ForceSum& forces = scene_forces.all();
  FrameDrives drives = CombDriveLoads(model, MakeCombDrives(scene, structure));
  if (FrameGapForce<ElectrostaticPressure>* electrodes = scene_forces.electrodes()) {
    forces.Add(*electrodes);
    drives.electrodes = electrodes;
    drives.electrode_voltage = MakeElectrodeDrive(scene);
  }
  FrameTransientResult out =
      RunFrameTransient(model, MakeFrameLoadCase(scene, structure), options, record,
                        forces.Empty() ? nullptr : &forces, drives, IsStraightBeam(scene) ? 1 : -1);
  for (const FrameRecordPoint& point : record) {
    results.recorded.push_back(point.node >= 0   ? structure.nodes[point.node].name
                               : point.body >= 0 ? structure.bodies[point.body].name
                                                 : OutputPointName(scene.structure.kind));
  }
  results.history = std::move(out.history);
  results.watched_component = out.watched_component;
  if (const FrameSubstrateContact* contact = scene_forces.contact()) {
    results.contact = FrameContactResults::Of(*contact, structure).contact;
    results.contact_lengths = HasContactLengths(structure);
    results.contact_events = contact->events();
  }
  return out.run;
}

TransientResult RunRod(const Scene& scene, const LoadCase& loads, const TransientOptions& options,
                       int& dofs) {
  const CosseratRod rod(MakeBeamDescription(scene));
  dofs = rod.FreeDofCount();
  return RunCosseratTransient(rod, RodLoadsFor(rod, loads), options);
}

// Whether the integrator's high-frequency spectral radius exceeds 0.6, above which impacts were
// measured to gain energy (tests/surface/contact_test.cpp): Newmark's trapezoidal rule (gamma =
// 1/2), HHT-alpha with alpha < 1/4 (rho_inf = (1 - alpha) / (1 + alpha)), generalised-alpha as
// given.
bool ContactGainsEnergy(const SceneAnalysis& analysis) {
  switch (analysis.integrator) {
    case Integrator::kNewmark:
      return analysis.gamma == 0.5;
    case Integrator::kHht:
      return analysis.alpha < 0.25;
    case Integrator::kGeneralizedAlpha:
      return analysis.rho_inf > 0.6;
    case Integrator::kCentralDifference:
    case Integrator::kModal:
      break;
  }
  return false;
}

}  // namespace

std::unique_ptr<TransientReport> TransientReport::Run(const Scene& scene) {
  RunHeader header = RunHeader::Start(scene);
  const LoadCase loads = MakeLoadCase(scene);
  const TransientOptions options = MakeTransientOptions(scene);
  const auto start = std::chrono::steady_clock::now();
  TransientResults results;
  const TransientResult result = scene.model.theory == Theory::kCosserat
                                     ? RunRod(scene, loads, options, header.dofs)
                                     : RunFrame(scene, options, header.dofs, results);
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.status = result.status;

  results.kind = scene.structure.kind;
  results.beam = IsStraightBeam(scene);
  results.integrator = scene.analysis.integrator;
  results.modes = std::min(scene.model.modes, header.dofs);
  results.initial = scene.analysis.initial;
  results.time_step_s = scene.analysis.time_step;
  results.steps = result.steps;
  results.simulated_time_s = result.simulated_time_s;
  results.step_time = result.step_time;
  results.realtime_factor =
      header.wall_time_s > 0.0 ? result.simulated_time_s / header.wall_time_s : 0.0;
  results.stepping_realtime_factor =
      result.stepping_time_s > 0.0 ? result.simulated_time_s / result.stepping_time_s : 0.0;
  results.max_abs_uy = result.max_abs_output;
  results.time_s = result.time_s;
  results.uy_m = result.output_m;

  if (scene.analysis.integrator == Integrator::kModal && scene.model.modes > header.dofs) {
    header.warnings.push_back("model.modes = " + std::to_string(scene.model.modes) +
                              " modes asked for, but the model has only " +
                              std::to_string(header.dofs));
  }
  const GeneralizedAlphaParameters& p = options.parameters;
  if (scene.model.theory == Theory::kCosserat && p.gamma == 0.5 && p.alpha_m == 0.0 &&
      p.alpha_f == 0.0) {
    header.warnings.push_back(
        "analysis.integrator = \"" + std::string(ToString(scene.analysis.integrator)) +
        "\" with gamma = 0.5 leaves the rod's axial and shear vibrations undamped, and large "
        "motions can pump energy into them until the step fails; \"generalized-alpha\" with "
        "rho_inf = 0.9 damps them and keeps the bending second-order accurate");
  }
  if (results.contact && ContactGainsEnergy(scene.analysis)) {
    header.warnings.push_back(
        "analysis.integrator = \"" + std::string(ToString(scene.analysis.integrator)) +
        "\" damps too little for contact: impacts can add energy (up to 14 % measured with "
        "average acceleration); \"generalized-alpha\" with rho_inf <= 0.6 adds none");
  }
  if (scene.loads.points.empty() && loads.points.empty() && loads.distributed.isZero(0.0)) {
    header.warnings.push_back(std::string("the loads are all zero: the ") +
                              (results.beam ? "beam" : "device") + " stays at rest");
  }
  // A device's substrate is checked by its static analysis, over every node and body corner.
  if (result.status == Status::kOk && !results.contact && results.beam) {
    header.WarnIfThroughSubstrate(
        std::string("the ") + OutputPointName(scene.structure.kind) + " moves",
        result.max_toward_substrate, scene.structure.gap);
  }
  return std::make_unique<TransientReport>(std::move(header), std::move(results));
}

void TransientReport::AddResults(nlohmann::ordered_json& json) const {
  json["steps"] = results_.steps;
  json["step_time_us"] = {{"median", results_.step_time.median_us},
                          {"p99", results_.step_time.p99_us},
                          {"max", results_.step_time.max_us},
                          {"batch", results_.step_time.batch}};
  json["realtime_factor"] = results_.realtime_factor;
  json["stepping_realtime_factor"] = results_.stepping_realtime_factor;
  if (!results_.beam) {
    json["displacement_max"] = results_.max_abs_uy;
    json["watched"] = {{"point", results_.recorded.front()},
                       {"component", std::string("u") + kAxes[results_.watched_component]}};
  } else {
    json[std::string(OutputPointName(results_.kind)) + "_displacement_max"] = results_.max_abs_uy;
  }
  json["simulated_time_s"] = results_.simulated_time_s;
  json["integrator"] = ToString(results_.integrator);
  json["time_step_s"] = results_.time_step_s;
  if (results_.contact) {
    json["contact"] = ContactJson(*results_.contact, results_.contact_lengths);
    json["contact_events"] = ContactEventsJson(results_.contact_events);
  }
}

void TransientReport::PrintResults(std::ostream& out) const {
  out << "integrator            " << ToString(results_.integrator);
  if (results_.integrator == Integrator::kModal) out << ", " << results_.modes << " modes";
  out << (results_.initial == InitialState::kStatic ? ", released from the static deflection"
                                                    : ", from rest")
      << "\n";
  out << "time step             " << Significant(results_.time_step_s) << " s\n";
  out << "steps                 " << results_.steps << " ("
      << Significant(results_.simulated_time_s) << " s simulated)\n";
  out << "step time             median " << Significant(results_.step_time.median_us, 3)
      << " us, p99 " << Significant(results_.step_time.p99_us, 3) << " us, max "
      << Significant(results_.step_time.max_us, 3) << " us";
  if (results_.step_time.batch > 1)
    out << " (per step, timed " << results_.step_time.batch << " at a time)";
  out << "\n";
  out << "realtime factor       " << Significant(results_.realtime_factor, 3)
      << " (model set-up included), " << Significant(results_.stepping_realtime_factor, 3)
      << " for the steps alone\n";
  const std::string label = !results_.beam
                                ? std::string("max |u") + kAxes[results_.watched_component] +
                                      "| at " + results_.recorded.front()
                                : std::string("max |uy| at ") + OutputPointName(results_.kind);
  // A long node name takes the column's width; one space still parts it from the value.
  out << label << std::string(label.size() < 22 ? 22 - label.size() : 1, ' ')
      << Scientific(results_.max_abs_uy) << " m\n";
  if (!results_.contact) return;
  PrintContact(out, *results_.contact, results_.contact_lengths);
  const ContactEvents& e = results_.contact_events;
  out << "contact events        " << e.proximity_warnings << " proximity warnings, " << e.contacts
      << " contacts, " << e.stuck << " stuck, " << e.releases << " releases\n";
}

void TransientReport::WriteFiles(const std::filesystem::path& directory) const {
  if (!results_.beam) {
    std::string columns = "time_s";
    for (const std::string& name : results_.recorded) {
      for (const char* axis : kAxes) columns += "," + name + "_u" + axis + "_m";
    }
    CsvFile csv(directory / "history.csv", columns);
    std::vector<std::string> row;
    for (std::size_t i = 0; i < results_.time_s.size(); ++i) {
      row.assign(1, CsvFile::Number(results_.time_s[i], kTimeDigits));
      for (Eigen::Index c = 0; c < results_.history.cols(); ++c) {
        row.push_back(CsvFile::Number(results_.history(static_cast<Eigen::Index>(i), c)));
      }
      csv.Row(row);
    }
    csv.Close();
    return;
  }
  CsvFile csv(directory / "history.csv",
              std::string("time_s,") + OutputPointName(results_.kind) + "_uy_m");
  for (std::size_t i = 0; i < results_.time_s.size(); ++i) {
    csv.Row({CsvFile::Number(results_.time_s[i], kTimeDigits), CsvFile::Number(results_.uy_m[i])});
  }
  csv.Close();
}

}  // namespace cosmems::internal
