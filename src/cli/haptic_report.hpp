#pragma once

#include <memory>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/haptics/device_types.hpp"
#include "cosmems/haptics/loop_stats.hpp"
#include "cosmems/haptics/safety_layer.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/scripted/scripted_sample.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems::internal {

/// A loop's tick times as JSON: {median, p99, max} in us.
nlohmann::ordered_json TimesJson(const LoopStats& stats);

/// What a haptic analysis reports, in SI (doc/cli.md, haptic).
struct HapticResults {
  LoopStats servo;    ///< the servo loop's figures
  LoopStats physics;  ///< the physics ticks' (its own thread when realtime, else in the servo)
  std::uint64_t failed_physics_ticks = 0;
  SafetyCounters safety;
  double force_limit_n = 0.0;
  ContactSummary contact;       ///< at the end
  ContactEvents events;         ///< over the run
  bool has_contact = false;     ///< the scene's substrate contact: its state is printed
  bool contact_lengths = true;  ///< the contact has lengths (HasContactLengths)
  double position_scale = 0.0, force_scale = 0.0;
  double coupling_n_per_m = 0.0, felt_coupling_n_per_m = 0.0, felt_structure_n_per_m = 0.0;
  std::string realtime_note;
  std::string device_model;                ///< from the device's specs
  std::vector<std::string> bounded_specs;  ///< specs the device reported beyond the table
  CalibrationStatus calibration = CalibrationStatus::kOk;  ///< when the loop started
  std::string hd_library;  ///< OpenHaptics: "sdk" or "fake"; empty for the scripted stylus
  std::vector<ScriptedSample> forces;  ///< scripted: every tick, stylus and the force sent to it
};

/// A stylus touching the beam or the device: a ScriptedDevice replaying [device].trajectory at the
/// analysis rate, or an OpenHapticsDevice (a PHANTOM Omni or Touch) for analysis.duration (30 s
/// when not given); a HapticLoop runs its physics (HapticStructure: the scene's
/// effects plus the probe) and renders the force through the safety layer. The scripted stylus
/// with realtime = true, and every real device, pace the ticks on the wall clock with the physics
/// on its own thread; the scripted stylus with realtime = false runs them as fast as possible
/// with the physics inside each tick, deterministically, and its ticks go to device_forces.csv in
/// --out.
class HapticReport final : public AnalysisReport {
 public:
  HapticReport(RunHeader header, HapticResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  static std::unique_ptr<HapticReport> Run(const Scene& scene);

  const HapticResults& results() const { return results_; }

  /// device_forces.csv: time_s, x_m, y_m, z_m, fx_n, fy_n, fz_n at every tick (device frame) of
  /// the scripted stylus.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  HapticResults results_;
};

}  // namespace cosmems::internal
