#pragma once

#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/device_types.hpp"
#include "cosmems/haptics/safety_layer.hpp"
#include "cosmems/scripted/spring_hand.hpp"

namespace cosmems {

/// What drives the ticks of a ScriptedDevice. Device time is always tick / rate, whatever the
/// clock, so all three give the same states and forces for the same script and client.
enum class ScriptedClock {
  kPaced,   ///< own thread, one tick per period of the wall clock, real-time priority if allowed
  kFast,    ///< own thread, ticks back to back (offline runs, throughput)
  kManual,  ///< no thread: the caller runs ticks with Step() (deterministic tests)
};

/// How the stylus moves relative to the script.
enum class HandModel {
  kRigid,   ///< the tip follows the script exactly; the force does not move it
  kSpring,  ///< a HandSpring pulls the tip toward the script against the device force
};

struct ScriptedOptions {
  ScriptedClock clock = ScriptedClock::kPaced;
  HandModel hand = HandModel::kRigid;
  HandSpring spring;  ///< used with HandModel::kSpring
  /// What the device reports; fields left at zero are filled from BuiltInSpecs(specs.model).
  DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  SafetyOptions safety;
  bool record = true;  ///< keep every tick for ScriptedDevice::Recorded() and WriteCsv()

  /// Throws std::invalid_argument naming the field and its value.
  void Validate() const;
};

}  // namespace cosmems
