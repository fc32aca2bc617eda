#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace cosmems {

/// What a haptic device can do, in SI (m, N, N/m, N s/m, Hz), in the device's own frame. A
/// backend reads what the device reports; HapticDevice fills the rest from BuiltInSpecs().
struct DeviceSpecs {
  std::string model;  ///< e.g. "PHANTOM Omni"
  std::string vendor;
  double max_force_n = 0.0;             ///< peak force the motors can exert
  double max_continuous_force_n = 0.0;  ///< force sustainable for hours
  double max_stiffness_n_per_m = 0.0;   ///< stiffest spring renderable at the nominal rate
  double max_damping_ns_per_m = 0.0;    ///< strongest renderable viscous damper
  double position_resolution_m = 0.0;   ///< encoder resolution at the tip
  Eigen::Vector3d workspace_min_m = Eigen::Vector3d::Zero();  ///< usable box, lower corner
  Eigen::Vector3d workspace_max_m = Eigen::Vector3d::Zero();  ///< usable box, upper corner
  double nominal_rate_hz = 1000.0;                            ///< servo rate the backend runs at
  int buttons = 0;
  /// Fields the device reported beyond the built-in table (infinite, NaN or above the
  /// datasheet), replaced by the table's values (CompleteSpecs).
  std::vector<std::string> bounded_fields;
};

/// The device at one servo tick, in SI in the device frame (OpenHaptics' axes: x right, y up,
/// z toward the user).
struct DeviceState {
  std::uint64_t tick = 0;  ///< ticks since the servo loop started
  double time_s = 0.0;     ///< device time at this tick (the backend's clock)
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();
  std::uint32_t buttons = 0;  ///< bit i: button i pressed
  bool fault = false;         ///< the device reported a force error on the previous command
  /// False while the device is not calibrated: its position is not to be trusted, the client is
  /// not asked and the force stays zero (it ramps in once the device is calibrated).
  bool calibrated = true;
};

/// What a servo client asks the device to push with. `valid` false or an `age_s` beyond the
/// safety layer's limit (the physics behind the force fell behind) makes the force zero.
struct ForceCommand {
  Eigen::Vector3d force_n = Eigen::Vector3d::Zero();  ///< on the hand, device frame
  bool valid = true;
  double age_s = 0.0;  ///< time since the model that produced the force was updated
};

/// Outcome of a device operation (set-up and start; the servo loop itself reports by counters).
enum class DeviceStatus {
  kOk,
  kNotFound,          ///< no device answered
  kAlreadyInUse,      ///< another program (or an earlier crash) holds it
  kNeedsCalibration,  ///< calibrate before forces are enabled
  kCommError,         ///< the link to the device or its scheduler failed
  kInvalidState,      ///< an operation out of order (start before open, ...)
  kRefused,           ///< a client whose tick may block (physics inside it) on a paced device
};

constexpr const char* ToString(DeviceStatus status) {
  switch (status) {
    case DeviceStatus::kOk:
      return "ok";
    case DeviceStatus::kNotFound:
      return "device not found";
    case DeviceStatus::kAlreadyInUse:
      return "device already in use";
    case DeviceStatus::kNeedsCalibration:
      return "device needs calibration";
    case DeviceStatus::kCommError:
      return "communication error";
    case DeviceStatus::kInvalidState:
      return "operation out of order";
    case DeviceStatus::kRefused:
      return "refused: a paced device cannot wait for physics inside its servo tick";
  }
  return "unknown";
}

/// A device's calibration, in OpenHaptics' three states.
enum class CalibrationStatus {
  kOk,
  kNeedsUpdate,       ///< the backend can update it itself
  kNeedsManualInput,  ///< the user must act (put the stylus in the inkwell)
};

constexpr const char* ToString(CalibrationStatus status) {
  switch (status) {
    case CalibrationStatus::kOk:
      return "calibrated";
    case CalibrationStatus::kNeedsUpdate:
      return "calibration needs an update";
    case CalibrationStatus::kNeedsManualInput:
      return "calibration needs the stylus in its inkwell";
  }
  return "unknown";
}

}  // namespace cosmems
