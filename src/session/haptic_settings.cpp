#include "cosmems/session/haptic_settings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/touch_target.hpp"
#include "cosmems/scripted/built_in_trajectory.hpp"
#include "cosmems/scripted/csv_trajectory.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {
namespace {

// A stiffness in a message, to five significant digits.
std::string FiveDigits(double value) {
  std::ostringstream out;
  out.precision(5);
  out << value;
  return out.str();
}

// What the built-in motions press: the upper face's point they press at [m], the thickness
// there [m] and the free structure's stiffness under a press there [N/m].
struct PressedPoint {
  Eigen::Vector3d face_m = Eigen::Vector3d::Zero();
  double thickness_m = 0.0;
  double stiffness_n_per_m = 0.0;
};

// The pressed point's upper face, its thickness there, and the stiffness 1 / (f^T K^-1 f) of the
// linear structure under a unit force f toward the substrate there.
PressedPoint ThePressedPoint(const Scene& scene) {
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure);
  const FrameRecordPoint where = TouchTarget(scene, structure);
  PressedPoint out;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  if (where.body >= 0) {
    const StructureBody& b = structure.bodies[where.body];
    out.thickness_m = b.size.y();
    centre = b.center;
  } else if (where.node >= 0) {
    for (const StructureMember& m : structure.members) {
      if (m.from == where.node || m.to == where.node)
        out.thickness_m = std::max(out.thickness_m, m.section.thickness);
    }
    centre = structure.nodes[where.node].position;
  } else {
    const StructureMember& m = structure.members[where.member];
    out.thickness_m = m.section.thickness;
    centre = (1.0 - where.at) * structure.nodes[m.from].position +
             where.at * structure.nodes[m.to].position;
  }
  out.face_m = centre + 0.5 * out.thickness_m * Eigen::Vector3d::UnitY();
  FrameLoadCase unit;
  unit.points.push_back({where.node, where.body, -Eigen::Vector3d::UnitY(), Eigen::Vector3d::Zero(),
                         where.member, where.at});
  // A unit of the model's internal force: 1 N assembled, times the force unit.
  const Eigen::VectorXd f = AssembleFrameLoads(model, unit) * model.units().force;
  Eigen::VectorXd u = f;
  BandCholesky(model.Stiffness()).SolveInPlace(u);
  const double compliance = f.dot(u) * model.units().length / model.units().force;  // m/N
  if (!(compliance > 0.0)) {
    const bool named = scene.device && scene.device->target;
    throw std::invalid_argument(std::string("device.target") +
                                (named ? " = \"" + *scene.device->target + "\"" : "") +
                                ": a press there moves nothing (it is anchored)");
  }
  out.stiffness_n_per_m = 1.0 / compliance;
  return out;
}

bool IsBuiltIn(const std::string& name) {
  for (const std::string& builtin : BuiltInTrajectoryNames()) {
    if (builtin == name) return true;
  }
  return false;
}

}  // namespace

DeviceSpecs ScriptedSpecs(const Scene& scene) {
  DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  specs.nominal_rate_hz = scene.analysis.rate;
  return specs;
}

HapticSettings MakeHapticSettings(const Scene& scene, const DeviceSpecs& specs) {
  const SceneDevice device = scene.device.value_or(SceneDevice{});
  const SceneStructure& s = scene.structure;
  HapticSettings out;
  out.specs = specs;
  const PressedPoint pressed = ThePressedPoint(scene);
  const double k_structure = pressed.stiffness_n_per_m;
  out.probe.radius = device.probe_radius.value_or(pressed.thickness_m);
  // 25 times the structure: the probe sinks 4 % of a press into the coupling, and the coupling,
  // the stiffest thing the hand can feel, stays within the device.
  out.probe.stiffness = device.coupling_stiffness.value_or(25.0 * k_structure);
  out.scaling.position_scale = device.position_scale.value_or(5000.0);
  const double renderable = out.specs.max_stiffness_n_per_m;
  out.scaling.force_scale = device.force_scale.value_or(
      0.5 * renderable * out.scaling.position_scale / out.probe.stiffness);
  out.felt_coupling_n_per_m = out.scaling.FeltStiffness(out.probe.stiffness);
  out.felt_structure_n_per_m = out.scaling.FeltStiffness(k_structure);
  if (out.felt_coupling_n_per_m > renderable) {
    throw std::invalid_argument("device.force_scale = " + FormatValue(out.scaling.force_scale) +
                                ": the hand would feel the coupling at " +
                                FiveDigits(out.felt_coupling_n_per_m) + " N/m, above the " +
                                FiveDigits(renderable) + " N/m the device renders stably");
  }

  // The probe's start: clear of the pressed face by the gap (or a thickness).
  const double clearance = s.gap.value_or(pressed.thickness_m);
  const Eigen::Vector3d start_micro =
      pressed.face_m + (out.probe.radius + clearance) * Eigen::Vector3d::UnitY();
  MotionShape shape;
  shape.depth_m = 2.2 * clearance * out.scaling.position_scale;
  // The sweep runs toward the start point along the beam, ending over it.
  const Eigen::Vector3d sweep_back(shape.sweep_m / out.scaling.position_scale, 0.0, 0.0);
  const bool sweep = device.trajectory == "sweep";
  const Eigen::Vector3d start_device(0.0, 0.5 * shape.depth_m, 0.0);
  out.scaling.device_origin_m =
      start_device - (sweep ? start_micro - sweep_back : start_micro) * out.scaling.position_scale;
  shape.start_m = start_device;
  const double duration = scene.analysis.duration;
  if (duration > 0.0) {
    // The scene reader bounds the duration to an hour: at most 1800 cycles, far inside int.
    shape.cycles = std::max(1, static_cast<int>(std::lround(duration / shape.period_s)));
    shape.period_s = duration / shape.cycles;
  }
  if (device.backend != DeviceBackend::kScripted) return out;
  try {
    out.trajectory = IsBuiltIn(device.trajectory) ? MakeBuiltInTrajectory(device.trajectory, shape)
                                                  : LoadCsvTrajectory(device.trajectory);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("device.trajectory: ") + e.what());
  }
  return out;
}

}  // namespace cosmems
