#include "cosmems/session/haptic_session.hpp"

#include <stdexcept>
#include <string>

#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "cosmems/scene/scene_conversion.hpp"
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

template <int Dim>
HapticSession<Dim>::HapticSession(const Scene& scene, OpenedDevice device,
                                  HapticPhysicsOptions physics)
    : opened_(std::move(device)),
      model_(MakeBeamDescription(scene), Dim == 3 ? DofNumbering::kByNode : DofNumbering::kByField),
      forces_(model_, scene),
      beam_(model_, opened_.settings.probe, forces_.All(), forces_.contact(),
            AtSceneRate(scene, physics)),
      loop_(beam_, LoopOptions(opened_)) {}

template <int Dim>
HapticSession<Dim>::~HapticSession() {
  Stop();
}

template <int Dim>
void HapticSession<Dim>::Start() {
  loop_.StartPhysics();
  if (opened_.device->Start(loop_) != DeviceStatus::kOk) {
    loop_.StopPhysics();
    std::string reason = "the servo loop did not start";
    if (opened_.openhaptics) reason += ": " + opened_.openhaptics->last_error().description;
    throw std::runtime_error("device.backend: " + reason);
  }
}

template <int Dim>
void HapticSession<Dim>::Stop() {
  opened_.device->Stop();
  loop_.StopPhysics();
}

template class HapticSession<2>;
template class HapticSession<3>;

}  // namespace cosmems
