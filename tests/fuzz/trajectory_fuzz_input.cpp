#include "trajectory_fuzz_input.hpp"

#include <cosmems/haptics/safety_layer.hpp>
#include <cosmems/scripted/csv_trajectory.hpp>
#include <cosmems/scripted/scripted_device.hpp>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cosmems::fuzz {
namespace {

/// A wall at y = 0 far stiffer than renderable: whatever the script does, the client asks for
/// large forces that the safety layer has to bound.
class StiffWall final : public ServoClient {
 public:
  void Tick(const DeviceState& state, ForceCommand& command) noexcept override {
    command.force_n = Eigen::Vector3d(0.0, -1e6 * state.position_m.y(), 0.0);
  }
};

constexpr std::uint64_t kMaxTicks = 2000;

void Play(std::unique_ptr<const Trajectory> trajectory, HandModel hand) {
  ScriptedOptions options;
  options.clock = ScriptedClock::kManual;
  options.hand = hand;
  options.record = false;  // a long script would otherwise fill memory before its first tick
  ScriptedDevice device(std::move(trajectory), options);
  StiffWall wall;
  if (device.Open() != DeviceStatus::kOk || device.Start(wall) != DeviceStatus::kOk) {
    std::fprintf(stderr, "the scripted device did not start\n");
    std::abort();
  }
  device.Step(kMaxTicks);
  device.Stop();
  const double limit = device.force_limit_n();
  if (!(device.safety_counters().max_force_n <= limit * (1.0 + 1e-12)) ||
      device.safety_counters().output_guards != 0) {
    std::fprintf(stderr, "the device sent %g N against a limit of %g N\n",
                 device.safety_counters().max_force_n, limit);
    std::abort();
  }
}

}  // namespace

void PlayFuzzedTrajectory(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    for (const HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
      std::istringstream in(text);
      Play(ReadCsvTrajectory(in, "fuzz.csv"), hand);
    }
  } catch (const std::invalid_argument&) {
    // The clear refusal bad input deserves.
  }
}

}  // namespace cosmems::fuzz
