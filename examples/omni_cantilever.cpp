// A PHANTOM Omni presses the cantilever: move the stylus down onto the beam (the device's centre
// is one gap above the tip), feel it bend, push it onto the substrate and feel it stick; the
// stylus's second button is "Reset Failure". Runs for the seconds given (default 30). Built
// against the OpenHaptics SDK when CMake finds it, otherwise against the project's fake of the HD
// API (the stylus then stays where the fake puts it).
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <thread>

#include "cosmems/openhaptics/openhaptics_device.hpp"
#include "touchable_cantilever.hpp"

int main(int argc, char** argv) {
  using namespace cosmems;
  const double seconds = argc > 1 ? std::atof(argv[1]) : 30.0;
  OpenHapticsDevice device;
  if (const DeviceStatus status = device.Open(); status != DeviceStatus::kOk) {
    std::cerr << "omni_cantilever: " << ToString(status) << ": " << device.last_error().description
              << "\n";
    return 1;
  }
  if (const CalibrationStatus c = device.Calibration(); c != CalibrationStatus::kOk) {
    std::cerr << "omni_cantilever: " << ToString(c) << "\n";
  }
  example::TouchableCantilever scene(device.specs(), PhysicsThread::kOwn);
  scene.loop().StartPhysics();
  if (device.Start(scene.loop()) != DeviceStatus::kOk) {
    std::cerr << "omni_cantilever: cannot start: " << device.last_error().description << "\n";
    return 1;
  }
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  ContactState shown = ContactState::kFree;
  while (std::chrono::steady_clock::now() < end && !device.servo_ended()) {
    if (scene.loop().UpdateFrame() && scene.loop().frame().contact.state != shown) {
      shown = scene.loop().frame().contact.state;
      std::cout << "beam: " << ToString(shown) << "\n";  // the paper's warning and stuck state
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(33));
  }
  device.Stop();
  scene.loop().StopPhysics();
  const LoopStats s = device.stats();
  std::cout << s.ticks << " ticks at " << s.rate_hz << " Hz, " << s.deadline_misses
            << " deadline misses; largest force " << device.safety_counters().max_force_n << " N\n";
  device.Close();
  return 0;
}
