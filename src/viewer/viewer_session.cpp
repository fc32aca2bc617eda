#include "viewer_session.hpp"

#include <stdexcept>

#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "mouse_device.hpp"

namespace cosmems::viewer {
namespace {

class RunningSession final : public ViewerSession {
 public:
  RunningSession(const Scene& scene, OpenedDevice device, const HapticPhysicsOptions& physics)
      : session_(scene, std::move(device), physics) {
    session_.Start();
  }

  bool UpdateFrame() override { return session_.loop().UpdateFrame(); }
  const HapticFrame& frame() const override { return session_.loop().frame(); }
  void RequestReset() override { session_.loop().RequestReset(); }
  void Stop() override { session_.Stop(); }
  std::string DeviceAlert() override {
    if (!session_.ServoFault().empty()) session_.Stop();
    return session_.DeviceAlert();
  }
  const OpenedDevice& opened() const override { return session_.opened(); }
  int dofs() const override { return session_.physics().DofCount(); }
  const LoopStats& physics_stats() const override { return session_.loop().physics_stats(); }
  std::uint64_t failed_ticks() const override { return session_.loop().failed_ticks(); }

  void SetInput(Input input, LiveTrajectory* hand, std::string note) {
    input_ = input;
    hand_ = hand;
    input_note_ = std::move(note);
  }

 private:
  HapticSession session_;
};

std::unique_ptr<ViewerSession> StartOn(const Scene& scene, OpenedDevice device,
                                       const HapticPhysicsOptions& physics, Input input,
                                       LiveTrajectory* hand, std::string note) {
  auto session = std::make_unique<RunningSession>(scene, std::move(device), physics);
  session->SetInput(input, hand, std::move(note));
  return session;
}

Scene WithBackend(const Scene& scene, DeviceBackend backend, bool realtime) {
  Scene out = scene;
  SceneDevice device = scene.device.value_or(SceneDevice{});
  device.backend = backend;
  device.realtime = realtime;
  out.device = device;
  return out;
}

}  // namespace

const char* ToString(Input input) {
  switch (input) {
    case Input::kAuto:
      return "auto";
    case Input::kMouse:
      return "mouse";
    case Input::kScript:
      return "script";
    case Input::kOmni:
      return "omni";
  }
  return "unknown";
}

std::unique_ptr<ViewerSession> ViewerSession::Start(const Scene& scene, Input input,
                                                    const HapticPhysicsOptions& physics) {
  std::string note;
  if (input == Input::kAuto) {
    if (!OpenHapticsDevice::BuiltWithSdk()) {
      note = "built without the OpenHaptics SDK: the mouse drives the stylus";
    } else {
      try {
        const Scene omni = WithBackend(scene, DeviceBackend::kOpenHaptics, true);
        return StartOn(omni, OpenDevice(omni), physics, Input::kOmni, nullptr, "");
      } catch (const std::runtime_error& e) {
        note = std::string("no haptic device (") + e.what() + "): the mouse drives the stylus";
      }
    }
    input = Input::kMouse;
  }
  if (input == Input::kMouse) {
    MouseDevice mouse = OpenMouseDevice(scene);
    return StartOn(scene, std::move(mouse.opened), physics, Input::kMouse, mouse.hand, note);
  }
  const Scene chosen = input == Input::kOmni ? WithBackend(scene, DeviceBackend::kOpenHaptics, true)
                                             : WithBackend(scene, DeviceBackend::kScripted, true);
  return StartOn(chosen, OpenDevice(chosen), physics, input, nullptr, note);
}

}  // namespace cosmems::viewer
