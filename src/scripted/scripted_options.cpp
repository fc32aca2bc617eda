#include "cosmems/scripted/scripted_options.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosmems {

void ScriptedOptions::Validate() const {
  safety.Validate();
  DeviceSpecs completed = specs;
  CompleteSpecs(completed);
  // CompleteSpecs() replaces a rate that is not positive; only an infinite one survives it.
  if (!std::isfinite(completed.nominal_rate_hz)) {
    throw std::invalid_argument(
        "specs.nominal_rate_hz = " + std::to_string(completed.nominal_rate_hz) + " must be finite");
  }
  if (hand == HandModel::kSpring) spring.Validate(1.0 / completed.nominal_rate_hz);
}

}  // namespace cosmems
