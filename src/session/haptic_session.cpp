#include "cosmems/session/haptic_session.hpp"

#include <optional>
#include <stdexcept>
#include <string>

#include "cosmems/analysis/comb_drive_force.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "cosmems/scripted/scripted_device.hpp"

namespace cosmems {
namespace {

// The tick is the period of the scene's rate; the scene's integrator picks the time path.
HapticPhysicsOptions AtSceneRate(const Scene& scene, HapticPhysicsOptions physics) {
  physics.tick_s = 1.0 / scene.analysis.rate;
  if (scene.analysis.integrator == Integrator::kModal) {
    physics.path = TimePath::kModal;
    physics.modes = scene.model.modes;
    physics.damping = MakeDampingModel(scene);
  }
  return physics;
}

HapticLoopOptions LoopOptions(const OpenedDevice& opened) {
  HapticLoopOptions options;
  options.scaling = opened.settings.scaling;
  options.physics = opened.paced ? PhysicsThread::kOwn : PhysicsThread::kServo;
  return options;
}

}  // namespace

OpenedDevice OpenDevice(const Scene& scene) {
  const SceneDevice device_scene = scene.device.value_or(SceneDevice{});
  OpenedDevice out;
  if (device_scene.backend == DeviceBackend::kScripted) {
    out.settings = MakeHapticSettings(scene, ScriptedSpecs(scene));
    ScriptedOptions options;
    options.clock = device_scene.realtime ? ScriptedClock::kPaced : ScriptedClock::kFast;
    options.specs = out.settings.specs;
    auto scripted = std::make_unique<ScriptedDevice>(std::move(out.settings.trajectory), options);
    out.scripted = scripted.get();
    out.device = std::move(scripted);
    out.paced = device_scene.realtime;
  } else {
    OpenHapticsOptions options;
    options.scheduler_rate_hz = static_cast<int>(scene.analysis.rate);
    auto openhaptics = std::make_unique<OpenHapticsDevice>(options);
    out.openhaptics = openhaptics.get();
    out.device = std::move(openhaptics);
    out.paced = true;
  }
  if (const DeviceStatus status = out.device->Open(); status != DeviceStatus::kOk) {
    std::string reason = ToString(status);
    if (out.openhaptics) reason += ": " + out.openhaptics->last_error().description;
    throw std::runtime_error("device.backend: the device did not open (" + reason + ")");
  }
  if (out.openhaptics) out.settings = MakeHapticSettings(scene, out.device->specs());
  return out;
}

// A structure (a beam's netlist or a device's) with every effect its scene declares: the
// substrate's (FrameSceneForces) and its transducers at their voltages, electrodes and combs,
// which the hand feels pull. Numbered for the probe's twist: a press off a member's axis twists
// it.
struct HapticSession::Touched {
  Touched(const Scene& scene, const ProbeOptions& probe, const HapticPhysicsOptions& options)
      : model(MakeStructureDescription(scene), MakeFrameCouplings(scene) | FrameCouplings::kTwist),
        forces(model, scene) {
    all.Add(forces.all());
    if (forces.electrodes()) all.Add(*forces.electrodes());
    if (!scene.effects.combs.empty()) {
      all.Add(combs.emplace(model, MakeCombDrives(scene, model.description())));
    }
    structure.emplace(model, probe, &all, forces.contact(), options);
  }
  HapticPhysics& physics() { return *structure; }

  FrameModel model;
  FrameSceneForces forces;
  std::optional<CombDriveForce> combs;
  ForceSum all;
  std::optional<HapticStructure> structure;
};

HapticSession::HapticSession(const Scene& scene, OpenedDevice device, HapticPhysicsOptions physics)
    : opened_(std::move(device)),
      touched_(
          std::make_unique<Touched>(scene, opened_.settings.probe, AtSceneRate(scene, physics))),
      loop_(touched_->physics(), LoopOptions(opened_)) {}

HapticSession::~HapticSession() { Stop(); }

const HapticPhysics& HapticSession::physics() const { return touched_->physics(); }

void HapticSession::Start() {
  loop_.StartPhysics();
  if (opened_.device->Start(loop_) != DeviceStatus::kOk) {
    loop_.StopPhysics();
    std::string reason = "the servo loop did not start";
    if (opened_.openhaptics) reason += ": " + opened_.openhaptics->last_error().description;
    throw std::runtime_error("device.backend: " + reason);
  }
}

std::string HapticSession::ServoFault() const {
  if (!opened_.openhaptics || !opened_.openhaptics->servo_ended()) return {};
  return "the device's scheduler stopped the servo loop (" +
         opened_.openhaptics->last_error().description + "); its motors are off";
}

std::string HapticSession::DeviceAlert() {
  std::string fault = ServoFault();
  if (!fault.empty()) return fault;
  const CalibrationStatus calibration = opened_.device->Calibration();
  if (calibration == CalibrationStatus::kOk) return {};
  return std::string("forces are off until the device is calibrated: ") + ToString(calibration);
}

void HapticSession::Stop() {
  opened_.device->Stop();
  loop_.StopPhysics();
}

}  // namespace cosmems
