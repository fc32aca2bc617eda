// A scripted stylus presses the cantilever's tip onto the substrate three times, paced at 1 kHz
// on the wall clock with the physics on its own thread, and prints what the hand felt and how
// the loops kept time. The same scene as `cosmems run cantilever-haptic`, in C++.
#include <chrono>
#include <iostream>
#include <thread>

#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/scripted/built_in_trajectory.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "touchable_cantilever.hpp"

int main() {
  using namespace cosmems;
  const DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  example::TouchableCantilever scene(specs, PhysicsThread::kOwn);
  MotionShape press;  // from 10 mm above the device's centre (the probe one gap over the tip)
  press.start_m = Eigen::Vector3d(0.0, 0.01, 0.0);
  press.depth_m = 0.032;  // 2.2 gaps of the beam at 5000 x: through the gap, onto the substrate
  ScriptedOptions options;
  options.clock = ScriptedClock::kPaced;
  options.specs = specs;
  ScriptedDevice device(MakeBuiltInTrajectory("press", press), options);
  if (device.Open() != DeviceStatus::kOk) return 1;
  scene.loop().StartPhysics();
  if (device.Start(scene.loop()) != DeviceStatus::kOk) return 1;
  int shown = 0;
  while (!device.Done()) {  // the display side, at 30 Hz
    if (scene.loop().UpdateFrame() && ++shown % 30 == 0) {
      const HapticFrame& f = scene.loop().frame();
      std::cout << "t = " << f.time_s << " s  tip " << scene.TipDeflection(f) * 1e6 << " um  probe "
                << f.probe_force_n.norm() * 1e6 << " uN  " << ToString(f.contact.state) << "\n";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(33));
  }
  device.Stop();
  scene.loop().StopPhysics();
  const LoopStats s = device.stats();
  std::cout << "servo: " << s.ticks << " ticks at " << s.rate_hz << " Hz, p99 "
            << s.ComputeQuantileUs(0.99) << " us, " << s.deadline_misses << " deadline misses"
            << (s.realtime ? " (real-time)" : "") << "\nphysics: p99 "
            << scene.loop().physics_stats().ComputeQuantileUs(0.99) << " us; largest force "
            << device.safety_counters().max_force_n << " N of " << device.force_limit_n() << " N\n";
  return 0;
}
