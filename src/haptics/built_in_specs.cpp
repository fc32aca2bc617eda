#include "cosmems/haptics/built_in_specs.hpp"

namespace cosmems {
namespace {

DeviceSpecs Make(const char* model, double max_force, double continuous, double stiffness,
                 double damping, double resolution, const Eigen::Vector3d& half_box) {
  DeviceSpecs s;
  s.model = model;
  s.vendor = "3D Systems";
  s.max_force_n = max_force;
  s.max_continuous_force_n = continuous;
  s.max_stiffness_n_per_m = stiffness;
  s.max_damping_ns_per_m = damping;
  s.position_resolution_m = resolution;
  s.workspace_min_m = -half_box;
  s.workspace_max_m = half_box;
  s.nominal_rate_hz = 1000.0;
  s.buttons = 2;
  return s;
}

}  // namespace

DeviceSpecs BuiltInSpecs(const std::string& model) {
  // Omni and Touch: one mechanism, 160 x 120 x 70 mm usable box, 0.055 mm resolution, 3.3 N peak
  // and 0.88 N continuous; CHAI3D's closed-loop stiffness and damping at 1 kHz.
  const Eigen::Vector3d omni_box(0.080, 0.060, 0.035);
  if (model.find("Omni") != std::string::npos) {
    return Make("PHANTOM Omni", 3.3, 0.88, 700.0, 5.0, 55e-6, omni_box);
  }
  if (model.find("Desktop") != std::string::npos || model.find("Touch X") != std::string::npos) {
    return Make("PHANTOM Desktop", 7.9, 1.75, 1000.0, 5.0, 23e-6,
                Eigen::Vector3d(0.080, 0.060, 0.060));
  }
  DeviceSpecs touch = Make("Touch", 3.3, 0.88, 400.0, 4.0, 55e-6, omni_box);
  if (!model.empty()) touch.model = model;
  return touch;
}

void CompleteSpecs(DeviceSpecs& reported) {
  const DeviceSpecs table = BuiltInSpecs(reported.model);
  auto fill = [](double& value, double fallback) {
    if (!(value > 0.0)) value = fallback;
  };
  // What the motors may be asked for is never taken from the device alone: a driver that
  // reports an infinite, NaN, negative or absurd force, stiffness or damping is held to the
  // datasheet's.
  auto bound = [&reported](double& value, double table_value, const char* field) {
    if (value == 0.0) {  // not reported
      value = table_value;
    } else if (!(value > 0.0 && value <= table_value)) {
      value = table_value;
      reported.bounded_fields.emplace_back(field);
    }
  };
  if (reported.model.empty()) reported.model = table.model;
  if (reported.vendor.empty()) reported.vendor = table.vendor;
  bound(reported.max_force_n, table.max_force_n, "max_force_n");
  bound(reported.max_continuous_force_n, table.max_continuous_force_n, "max_continuous_force_n");
  bound(reported.max_stiffness_n_per_m, table.max_stiffness_n_per_m, "max_stiffness_n_per_m");
  bound(reported.max_damping_ns_per_m, table.max_damping_ns_per_m, "max_damping_ns_per_m");
  fill(reported.position_resolution_m, table.position_resolution_m);
  fill(reported.nominal_rate_hz, table.nominal_rate_hz);
  const bool box_reported =
      !(reported.workspace_min_m.isZero() && reported.workspace_max_m.isZero());
  const bool box_finite =
      reported.workspace_min_m.allFinite() && reported.workspace_max_m.allFinite();
  if (box_reported && !box_finite) reported.bounded_fields.emplace_back("workspace");
  if (!box_reported || !box_finite) {
    reported.workspace_min_m = table.workspace_min_m;
    reported.workspace_max_m = table.workspace_max_m;
  }
  if (reported.buttons <= 0) reported.buttons = table.buttons;
}

}  // namespace cosmems
