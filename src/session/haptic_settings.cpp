#include "cosmems/session/haptic_settings.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cosmems/core/validation.hpp"
#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/scripted/built_in_trajectory.hpp"
#include "cosmems/scripted/csv_trajectory.hpp"

namespace cosmems {
namespace {

// A stiffness in a message, to five significant digits.
std::string FiveDigits(double value) {
  std::ostringstream out;
  out.precision(5);
  out << value;
  return out.str();
}

// The free structure's stiffness under the probe's start point: 3EI/L^3 at a cantilever's tip,
// 192EI/L^3 at a bridge's midspan.
double StructureStiffness(const Scene& scene) {
  const SceneStructure& s = scene.structure;
  const double ei = scene.material.young_modulus * s.width * std::pow(s.thickness, 3) / 12.0;
  const double factor = s.kind == StructureKind::kCantilever ? 3.0 : 192.0;
  return factor * ei / std::pow(s.length, 3);
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
  const double k_structure = StructureStiffness(scene);
  out.probe.radius = device.probe_radius.value_or(s.thickness);
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

  // The probe's start: clear of the face by the gap (or a thickness), over the tip or midspan.
  const double clearance = s.gap.value_or(s.thickness);
  const double x = s.kind == StructureKind::kCantilever ? s.length : 0.5 * s.length;
  const Eigen::Vector3d start_micro(x, 0.5 * s.thickness + out.probe.radius + clearance, 0.0);
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
