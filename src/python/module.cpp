#include <pybind11/pybind11.h>

#include "bindings.hpp"

// The compiled half of the `cosmems` package; cosmems/__init__.py is the other (Scene, run,
// sweep and the conversions to numpy).
PYBIND11_MODULE(_cosmems, m) {
  m.doc() = "cosmems' C++ library: scenes, analyses, sweeps, models and steppers";
  cosmems::python::BindErrors(m);
  cosmems::python::BindScenes(m);
  cosmems::python::BindModels(m);
}
