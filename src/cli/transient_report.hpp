#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "analysis_report.hpp"
#include "cosmems/analysis/step_timing.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems::internal {

/// What a transient run reports, in SI (doc/cli.md, transient). uy is recorded at the free end
/// of a cantilever or, as an extension for bridges, at mid-span; a device records the motion of
/// its bodies' centres and the nodes of analysis.record, and watches one component of the first.
struct TransientResults {
  StructureKind kind = StructureKind::kCantilever;  ///< names the output point: tip or midspan
  bool beam = true;  ///< a cantilever or a bridge: uy at its tip or midspan, as history.csv
  Integrator integrator = Integrator::kNewmark;
  int modes = 0;  ///< modes propagated by the "modal" integrator
  InitialState initial = InitialState::kRest;
  double time_step_s = 0.0;
  long steps = 0;  ///< steps taken
  double simulated_time_s = 0.0;
  StepTiming step_time;          ///< per-step compute time [us]
  double realtime_factor = 0.0;  ///< simulated time over the header's wall time
  /// simulated time over the time spent in steps only: whether the stepping keeps up with
  /// real time once the model is built
  double stepping_realtime_factor = 0.0;
  double max_abs_uy = 0.0;     ///< m: largest |uy| at the output point (a device: |u_watched|)
  std::vector<double> time_s;  ///< the recorded history
  std::vector<double> uy_m;
  // A device's recorded points, in the order of history's columns (ux, uy, uz of each), and the
  // watched one: the first point's component its static response to the loads is largest in.
  std::vector<std::string> recorded;
  Eigen::MatrixXd history;
  int watched_component = 1;
  std::optional<ContactSummary> contact;  ///< at the end, with contact declared
  bool contact_lengths = false;           ///< whether `contact` has lengths (HasContactLengths)
  ContactEvents contact_events;
};

/// A linear transient run: the JSON fields of doc/cli.md and history.csv.
///
/// JSON: `steps`, `step_time_us` {`median`, `p99`, `max`}, `realtime_factor` (simulated time
/// over `wall_time_s`, which includes building the model), and `tip_displacement_max` (the
/// largest |uy| at the tip, m) for a cantilever or `midspan_displacement_max` for a bridge (an
/// extension). Further extensions: `simulated_time_s`, `integrator`, `time_step_s`. A device
/// reports `displacement_max` (the largest |u| of its watched component) and `watched`
/// {`point`, `component`} instead of the tip's.
class TransientReport final : public AnalysisReport {
 public:
  TransientReport(RunHeader header, TransientResults results)
      : AnalysisReport(std::move(header)), results_(std::move(results)) {}

  /// Builds the scene's model and runs its transient analysis.
  static std::unique_ptr<TransientReport> Run(const Scene& scene);

  const TransientResults& results() const { return results_; }

  /// history.csv: time_s and tip_uy_m (cantilever) or midspan_uy_m (bridge), one row per
  /// recorded sample; a device: time_s and NAME_ux_m, NAME_uy_m, NAME_uz_m of each recorded
  /// point.
  void WriteFiles(const std::filesystem::path& directory) const override;

 protected:
  void AddResults(nlohmann::ordered_json& json) const override;
  void PrintResults(std::ostream& out) const override;

 private:
  TransientResults results_;
};

}  // namespace cosmems::internal
