#pragma once

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/scene/scene.hpp"

namespace cosmems::python {

/// A numerical failure of a library call (a factorisation, a step): cosmems.NumericalError.
class NumericalFailure : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The scene `name_or_path` (an embedded name or a .toml file) with the --set assignments
/// `sets` ("KEY=VALUE", VALUE as TOML) applied and validated. Throws SceneError.
Scene LoadWith(const std::string& name_or_path, const std::vector<std::string>& sets);

/// cosmems.SceneError, cosmems.NumericalError and their translation from C++.
void BindErrors(pybind11::module_& m);
/// scenes(), check_scene(), scene_text(), run() and sweep(): the CLI's commands.
void BindScenes(pybind11::module_& m);
/// Model and Stepper: the matrices, static and modal solves and a time loop.
void BindModels(pybind11::module_& m);

}  // namespace cosmems::python
