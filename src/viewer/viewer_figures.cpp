#include "viewer_figures.hpp"

#include <nlohmann/json.hpp>
#include <ostream>

#include "contact_report.hpp"
#include "haptic_report.hpp"

namespace cosmems::viewer {

void PrintFigures(const ViewerFigures& f, std::ostream& out) {
  out << f.scene << ": " << f.input << " stylus (" << f.device << "), " << f.width << "x"
      << f.height << "\n";
  out << "display      " << f.frames << " frames at " << f.display_rate_hz
      << " Hz, longest interval " << f.frame_interval_max_ms << " ms, work median "
      << f.draw_median_ms << " ms, max " << f.draw_max_ms << " ms\n";
  const LoopStats& s = f.servo;
  out << "servo        " << s.ticks << " ticks at " << s.rate_hz << " Hz"
      << (s.realtime ? " (real-time)" : "") << ", tick median " << s.ComputeQuantileUs(0.5)
      << " us, p99 " << s.ComputeQuantileUs(0.99) << " us, max " << s.compute_max_us
      << " us, deadline misses " << s.deadline_misses << "\n";
  const LoopStats& p = f.physics;
  out << "physics      " << p.ticks << " ticks, median " << p.ComputeQuantileUs(0.5) << " us, p99 "
      << p.ComputeQuantileUs(0.99) << " us, max " << p.compute_max_us << " us, "
      << f.failed_physics_ticks << " failed\n";
  out << "beam         " << ToString(f.contact.state);
  if (f.contact.Stuck()) out << " (" << Describe(f.contact.shape) << ")";
  out << "; " << f.events.proximity_warnings << " proximity warnings, " << f.events.contacts
      << " contacts, " << f.events.stuck << " stuck, " << f.events.releases << " releases\n";
  if (!f.realtime_note.empty()) out << "real-time    " << f.realtime_note << "\n";
  if (!f.screenshot.empty()) out << "screenshot   " << f.screenshot << "\n";
}

void PrintFiguresJson(const ViewerFigures& f, std::ostream& out) {
  nlohmann::ordered_json json;
  json["scene"] = f.scene;
  json["input"] = f.input;
  json["device"] = f.device;
  json["window"] = {f.width, f.height};
  json["frames"] = f.frames;
  json["display_rate_hz"] = f.display_rate_hz;
  json["frame_interval_max_ms"] = f.frame_interval_max_ms;
  json["draw_ms"] = {{"median", f.draw_median_ms}, {"max", f.draw_max_ms}};
  json["servo"] = {{"ticks", f.servo.ticks},
                   {"rate_hz", f.servo.rate_hz},
                   {"realtime", f.servo.realtime},
                   {"tick_time_us", internal::TimesJson(f.servo)},
                   {"deadline_misses", f.servo.deadline_misses},
                   {"period_max_us", f.servo.period_max_us}};
  json["physics"] = {{"ticks", f.physics.ticks},
                     {"failed_ticks", f.failed_physics_ticks},
                     {"tick_time_us", internal::TimesJson(f.physics)}};
  json["contact_state"] = ToString(f.contact.state);
  json["contact_shape"] = ToString(f.contact.shape);
  json["contact_events"] = internal::ContactEventsJson(f.events);
  json["realtime_note"] = f.realtime_note;
  json["screenshot"] = f.screenshot;
  out << json.dump() << "\n";
}

}  // namespace cosmems::viewer
