#pragma once

#include <string>

namespace cosmems {

/// Every key a scene file takes, one markdown table row each: the key, what it accepts (type,
/// sign, bounds, unit), its default and its meaning, from the same description the scene reader
/// reads and validates by. `cosmems keys` prints it; doc/scenes.md holds it.
std::string SceneKeyReference();

}  // namespace cosmems
