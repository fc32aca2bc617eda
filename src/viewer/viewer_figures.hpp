#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

#include "cosmems/haptics/loop_stats.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems::viewer {

/// What a viewer run measured: the display loop's pace beside the servo loop's figures over the
/// same time, so that one run shows both targets (30 Hz drawn, 1 kHz felt).
struct ViewerFigures {
  std::string scene;
  std::string input;       ///< "mouse", "script" or "omni"
  std::string device;      ///< the device's model
  std::string screenshot;  ///< the PNG written (headless), else empty
  int width = 0, height = 0;
  std::uint64_t frames = 0;
  double display_rate_hz = 0.0;        ///< frames over the wall time between the first and last
  double frame_interval_max_ms = 0.0;  ///< longest time between two frames
  double draw_median_ms = 0.0;         ///< a frame's work (input, meshes, drawing), median
  double draw_max_ms = 0.0;
  LoopStats servo;    ///< the device's servo loop
  LoopStats physics;  ///< the physics thread's ticks
  std::uint64_t failed_physics_ticks = 0;
  std::string realtime_note;  ///< the scripted devices: how real-time scheduling went
  ContactSummary contact;     ///< at the end
  ContactEvents events;       ///< over the last model's session
};

/// A few lines for people.
void PrintFigures(const ViewerFigures& figures, std::ostream& out);
/// One JSON object on one line.
void PrintFiguresJson(const ViewerFigures& figures, std::ostream& out);

}  // namespace cosmems::viewer
