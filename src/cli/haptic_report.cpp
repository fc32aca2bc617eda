#include "haptic_report.hpp"

#include <chrono>
#include <iostream>
#include <sstream>
#include <thread>

#include "atomic_file.hpp"
#include "contact_report.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "cosmems/session/haptic_session.hpp"
#include "frame_contact_output.hpp"
#include "text_format.hpp"

namespace cosmems::internal {

nlohmann::ordered_json TimesJson(const LoopStats& s) {
  return {{"median", s.ComputeQuantileUs(0.5)},
          {"p99", s.ComputeQuantileUs(0.99)},
          {"max", s.ComputeQuantileUs(1.0)}};
}

namespace {

// How long an Omni session lasts when the scene does not say [s].
constexpr double kDefaultSessionS = 30.0;

// Runs the servo loop until the scripted stylus ends, or for the scene's duration on a real
// device (sooner if its scheduler fails).
void RunSession(const Scene& scene, const OpenedDevice& opened) {
  if (opened.scripted) {
    opened.scripted->WaitUntilDone();
    return;
  }
  const double seconds = scene.analysis.duration > 0.0 ? scene.analysis.duration : kDefaultSessionS;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end && !opened.openhaptics->servo_ended()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

std::unique_ptr<HapticReport> HapticReport::Run(const Scene& scene) {
  const SceneDevice device_scene = scene.device.value_or(SceneDevice{});
  RunHeader header = RunHeader::Start(scene);
  const auto start = std::chrono::steady_clock::now();
  HapticSession session(scene, OpenDevice(scene));
  const OpenedDevice& opened = session.opened();
  HapticDevice& device = session.device();
  const HapticSettings& settings = session.settings();
  HapticLoop& loop = session.loop();

  HapticResults r;
  r.device_model = device.specs().model;
  r.bounded_specs = device.specs().bounded_fields;
  r.calibration = device.Calibration();
  if (r.calibration != CalibrationStatus::kOk) {
    // Said now, not after the run: the person at the device has to act for forces to come on.
    std::cerr << "cosmems: " << session.DeviceAlert() << "\n";
  }
  session.Start();
  RunSession(scene, opened);
  session.Stop();
  header.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  header.dofs = session.physics().DofCount();
  r.servo = device.stats();
  r.physics = loop.physics_stats();
  r.failed_physics_ticks = loop.failed_ticks();
  r.safety = device.safety_counters();
  r.force_limit_n = device.force_limit_n();
  loop.UpdateFrame();
  r.contact = loop.frame().contact;
  r.has_contact = scene.effects.HasContact();
  r.contact_lengths = HasContactLengths(MakeStructureDescription(scene));
  r.events = loop.frame().events;
  r.position_scale = settings.scaling.position_scale;
  r.force_scale = settings.scaling.force_scale;
  r.coupling_n_per_m = settings.probe.stiffness;
  r.felt_coupling_n_per_m = settings.felt_coupling_n_per_m;
  r.felt_structure_n_per_m = settings.felt_structure_n_per_m;
  if (opened.scripted) {
    r.realtime_note = opened.scripted->realtime_note();
    r.forces = opened.scripted->Recorded();
  } else {
    r.hd_library = OpenHapticsDevice::BuiltWithSdk() ? "sdk" : "fake";
    if (!OpenHapticsDevice::BuiltWithSdk()) {
      header.warnings.push_back(
          "built without the OpenHaptics SDK: the device is the project's fake of the HD API, "
          "whose stylus stands still");
    }
    if (const std::string fault = session.ServoFault(); !fault.empty()) {
      header.warnings.push_back(fault);
    }
  }
  device.Close();
  if (r.failed_physics_ticks > 0) {
    header.warnings.push_back(std::to_string(r.failed_physics_ticks) +
                              " physics ticks failed; the safety layer held the force at zero "
                              "until the next good one");
  }
  for (const std::string& field : r.bounded_specs) {
    header.warnings.push_back("the device reported " + field +
                              " beyond the built-in table's value for its model; the table's "
                              "value is used");
  }
  if (r.calibration != CalibrationStatus::kOk) {
    header.warnings.push_back(std::string("device calibration at the start: ") +
                              ToString(r.calibration) + "; forces were held off for " +
                              std::to_string(r.safety.uncalibrated_ticks) +
                              " ticks until it was calibrated");
  }
  if (device_scene.realtime && !r.servo.realtime && !r.realtime_note.empty()) {
    header.warnings.push_back("not real-time: " + r.realtime_note);
  }
  return std::make_unique<HapticReport>(std::move(header), std::move(r));
}

void HapticReport::AddResults(nlohmann::ordered_json& json) const {
  const HapticResults& r = results_;
  json["ticks"] = r.servo.ticks;
  json["tick_time_us"] = TimesJson(r.servo);
  json["deadline_misses"] = r.servo.deadline_misses;
  json["max_device_force_n"] = r.safety.max_force_n;
  json["force_limit_n"] = r.force_limit_n;
  json["stuck_events"] = r.events.stuck;
  json["proximity_warnings"] = r.events.proximity_warnings;
  json["rate_hz"] = r.servo.rate_hz;
  json["paced"] = r.servo.paced;
  json["realtime"] = r.servo.realtime;
  json["overruns"] = r.servo.overruns;
  json["physics"] = {{"ticks", r.physics.ticks},
                     {"failed_ticks", r.failed_physics_ticks},
                     {"tick_time_us", TimesJson(r.physics)}};
  json["safety"] = {{"clamped", r.safety.clamped},
                    {"slew_limited", r.safety.slew_limited},
                    {"ramp_ticks", r.safety.ramp_ticks},
                    {"stale_forces", r.safety.stale_forces},
                    {"non_finite_states", r.safety.non_finite_states},
                    {"out_of_range_states", r.safety.out_of_range_states},
                    {"non_finite_forces", r.safety.non_finite_forces},
                    {"device_faults", r.safety.device_faults},
                    {"passivity_activations", r.safety.passivity_activations},
                    {"output_guards", r.safety.output_guards},
                    {"ramp_down_ticks", r.safety.ramp_down_ticks},
                    {"uncalibrated_ticks", r.safety.uncalibrated_ticks}};
  json["scaling"] = {{"position_scale", r.position_scale},
                     {"force_scale", r.force_scale},
                     {"coupling_stiffness_n_per_m", r.coupling_n_per_m},
                     {"felt_coupling_n_per_m", r.felt_coupling_n_per_m},
                     {"felt_structure_n_per_m", r.felt_structure_n_per_m}};
  json["contact"] = ContactJson(r.contact, r.contact_lengths);
  json["contact_events"] = ContactEventsJson(r.events);
  json["device"] = {{"backend", r.hd_library.empty() ? "scripted" : "openhaptics"},
                    {"model", r.device_model},
                    {"calibration", ToString(r.calibration)},
                    {"bounded_specs", r.bounded_specs}};
  if (!r.hd_library.empty()) json["device"]["hd_library"] = r.hd_library;
}

void HapticReport::PrintResults(std::ostream& out) const {
  const HapticResults& r = results_;
  const LoopStats& s = r.servo;
  out << "device                " << r.device_model
      << (r.hd_library.empty() ? " (scripted)" : " (OpenHaptics, " + r.hd_library + " HD library)")
      << "\n";
  out << "servo ticks           " << s.ticks << " at " << Significant(s.rate_hz, 6) << " Hz ("
      << (s.paced ? "paced" : "as fast as possible") << (s.realtime ? ", real-time" : "") << ")\n";
  out << "tick time             median " << Significant(s.ComputeQuantileUs(0.5), 3) << " us, p99 "
      << Significant(s.ComputeQuantileUs(0.99), 3) << " us, max "
      << Significant(s.compute_max_us, 3) << " us\n";
  out << "deadline misses       " << s.deadline_misses << ", overruns " << s.overruns << "\n";
  out << "physics tick          median " << Significant(r.physics.ComputeQuantileUs(0.5), 3)
      << " us, p99 " << Significant(r.physics.ComputeQuantileUs(0.99), 3) << " us, max "
      << Significant(r.physics.compute_max_us, 3) << " us\n";
  out << "device force          max " << Significant(r.safety.max_force_n, 3) << " N (limit "
      << Significant(r.force_limit_n, 3) << " N, clamped " << r.safety.clamped << " ticks)\n";
  out << "felt stiffness        coupling " << Significant(r.felt_coupling_n_per_m, 3)
      << " N/m, structure " << Significant(r.felt_structure_n_per_m, 3) << " N/m\n";
  out << "events                " << r.events.proximity_warnings << " proximity warnings, "
      << r.events.contacts << " contacts, " << r.events.stuck << " stuck, " << r.events.releases
      << " releases\n";
  if (r.has_contact) PrintContact(out, r.contact, r.contact_lengths);
}

void HapticReport::WriteFiles(const std::filesystem::path& directory) const {
  if (!results_.hd_library.empty()) return;  // a real device's ticks are not recorded
  std::ostringstream text;
  WriteSamplesCsv(text, results_.forces);
  AtomicFile::WriteWhole(directory / "device_forces.csv", text.str());
}

}  // namespace cosmems::internal
