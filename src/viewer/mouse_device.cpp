#include "mouse_device.hpp"

#include <memory>
#include <stdexcept>
#include <string>

#include "cosmems/scripted/scripted_device.hpp"

namespace cosmems::viewer {

MouseDevice OpenMouseDevice(const Scene& scene) {
  Scene scripted = scene;
  SceneDevice device = scene.device.value_or(SceneDevice{});
  device.backend = DeviceBackend::kScripted;  // the settings then include the script's start
  scripted.device = device;
  MouseDevice out;
  OpenedDevice& opened = out.opened;
  opened.settings = MakeHapticSettings(scripted, ScriptedSpecs(scripted));
  auto hand = std::make_unique<LiveTrajectory>(opened.settings.trajectory->Position(0.0));
  out.hand = hand.get();
  opened.settings.trajectory.reset();
  ScriptedOptions options;
  options.clock = ScriptedClock::kPaced;
  options.record = false;
  options.specs = opened.settings.specs;
  auto mouse = std::make_unique<ScriptedDevice>(std::move(hand), options);
  opened.scripted = mouse.get();
  opened.device = std::move(mouse);
  opened.paced = true;
  if (const DeviceStatus status = opened.device->Open(); status != DeviceStatus::kOk) {
    throw std::runtime_error(std::string("mouse: the scripted device did not open (") +
                             ToString(status) + ")");
  }
  return out;
}

}  // namespace cosmems::viewer
