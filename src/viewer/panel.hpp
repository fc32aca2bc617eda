#pragma once

#include <string>

#include "cosmems/haptics/haptic_frame.hpp"
#include "cosmems/haptics/loop_stats.hpp"
#include "display_space.hpp"
#include "live_plots.hpp"
#include "model_settings.hpp"

namespace cosmems::viewer {

/// What the panel shows about the running session.
struct PanelStatus {
  std::string scene;         ///< the scene's source
  std::string device;        ///< the stylus: model and backend
  std::string input_note;    ///< why the input is not what was asked for, if it is not
  std::string device_alert;  ///< HapticSession::DeviceAlert(): a failed servo, no calibration
  int dofs = 0;              ///< of the running model
  const HapticFrame* frame = nullptr;
  LoopStats servo;               ///< the device's figures so far
  double display_rate_hz = 0.0;  ///< frames drawn per second of wall time
  double frame_interval_max_ms = 0.0;
  std::string error;  ///< why the last edit was refused (empty: it was applied)
};

/// What the user asked for this frame.
struct PanelActions {
  bool rebuild = false;  ///< an edit was completed: apply draft()
  bool reset = false;    ///< "Reset Failure"
};

/// The panel on the left: the session's state with the "Reset Failure" button, the live plots
/// and the loop figures, then the model's settings. Edits go to a draft; completing one (Enter
/// or leaving a field, letting go of a slider, a click on a box or a choice) asks for a rebuild.
class Panel {
 public:
  explicit Panel(const ModelSettings& settings) : draft_(settings) {}

  /// Draws the panel over the window's left kPanelWidth pixels, `height` high.
  PanelActions Draw(const PanelStatus& status, const LivePlots& plots, DisplaySpace& space,
                    float height);

  const ModelSettings& draft() const { return draft_; }

 private:
  void DrawState(const PanelStatus& status, PanelActions& actions) const;
  void DrawFigures(const PanelStatus& status) const;
  bool DrawStructure();
  bool DrawSubstrateAndMaterial();
  bool DrawModel();
  bool DrawEffects();

  ModelSettings draft_;
};

}  // namespace cosmems::viewer
