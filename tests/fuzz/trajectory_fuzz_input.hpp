#pragma once

#include <cstddef>
#include <cstdint>

namespace cosmems::fuzz {

/// Feeds one input to the CSV trajectory reader as a file's content; a trajectory it accepts is
/// played through a ScriptedDevice (rigid and spring hands) against a stiff wall for up to 2000
/// ticks. std::invalid_argument (the reader's and the device's refusals) is the only exception
/// bad input may raise. A force the device sent beyond the safety layer's bounds aborts.
void PlayFuzzedTrajectory(const std::uint8_t* data, std::size_t size);

}  // namespace cosmems::fuzz
