#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "analysis_runner.hpp"
#include "bindings.hpp"
#include "cosmems/scene/embedded_scenes.hpp"
#include "cosmems/scene/scene_error.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "sweep_request.hpp"
#include "sweep_runner.hpp"

namespace py = pybind11;

namespace cosmems::python {
namespace {

// `cosmems sweep --json`: the summary JSON and the rows as one JSON array.
std::pair<std::string, std::string> Sweep(internal::SweepRequest request) {
  request.json = true;
  std::ostringstream out, err;
  std::vector<internal::SweepRow> rows;
  internal::RunSweep(request, out, err, false, &rows);
  nlohmann::ordered_json array = nlohmann::ordered_json::array();
  for (const internal::SweepRow& row : rows) array.push_back(row.Json());
  return {out.str(), array.dump()};
}

}  // namespace

Scene LoadWith(const std::string& name_or_path, const std::vector<std::string>& sets) {
  std::vector<SceneOverride> overrides;
  for (const std::string& assignment : sets) overrides.push_back(SceneOverride::Parse(assignment));
  return LoadScene(name_or_path, overrides);
}

void BindScenes(py::module_& m) {
  m.def(
      "scenes",
      [] {
        std::vector<std::pair<std::string, std::string>> out;
        for (const EmbeddedScene& scene : EmbeddedScenes()) {
          out.emplace_back(scene.name, scene.description);
        }
        return out;
      },
      "The embedded scenes: (name, one-line description) pairs.");
  m.def("scene_text", &internal::SceneText, py::arg("scene"),
        "The TOML text of an embedded scene or a scene file.");
  m.def(
      "check_scene",
      [](const std::string& scene, const std::vector<std::string>& sets) {
        (void)LoadWith(scene, sets);
      },
      py::arg("scene"), py::arg("sets"), "Loads and validates; raises SceneError.");
  m.def(
      "run",
      [](const std::string& scene, const std::vector<std::string>& sets, const std::string& out) {
        const std::unique_ptr<internal::AnalysisReport> report =
            internal::RunAnalysis(LoadWith(scene, sets));
        const bool ok = report->header().status == Status::kOk;
        if (ok && !out.empty()) report->WriteFiles(out);
        return std::make_pair(report->Json().dump(), ok);
      },
      py::arg("scene"), py::arg("sets"), py::arg("out"), py::call_guard<py::gil_scoped_release>(),
      "Runs the scene's analysis: (the JSON result, whether its status is ok). With `out` (an "
      "existing directory) the CSV files of `cosmems run --out` are written there.");
  using internal::SweepRequest;
  py::class_<SweepRequest>(m, "SweepRequest", "The options of `cosmems sweep`, named as there.")
      .def(py::init<>())
      .def_readwrite("scene", &SweepRequest::scene)
      .def_readwrite("sets", &SweepRequest::sets)
      .def_readwrite("vary", &SweepRequest::vary)
      .def_readwrite("specs", &SweepRequest::specs)
      .def_readwrite("plots", &SweepRequest::plots)
      .def_readwrite("method", &SweepRequest::method)
      .def_readwrite("samples", &SweepRequest::samples)
      .def_readwrite("seed", &SweepRequest::seed)
      .def_readwrite("threads", &SweepRequest::threads)
      .def("set_shard", &SweepRequest::SetShard, py::arg("text"), "--shard K/N")
      .def_readwrite("out", &SweepRequest::out);
  m.def("sweep", &Sweep, py::arg("request"), py::call_guard<py::gil_scoped_release>(),
        "`cosmems sweep`: (the summary JSON, the rows as a JSON array).");
}

void BindErrors(py::module_& m) {
  static py::exception<SceneError> scene_error(m, "SceneError", PyExc_ValueError);
  static py::exception<NumericalFailure> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  // Bad input is the CLI's exit 2 (SceneError, the CLI's own input errors, the core's checks):
  // one exception, with the key, the value and the source when the scene names them.
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const SceneError& e) {
      py::object error = py::handle(scene_error.ptr())(e.what());
      error.attr("key") = e.key();
      error.attr("value") = e.value();
      error.attr("source") = e.source();
      PyErr_SetObject(scene_error.ptr(), error.ptr());
    } catch (const std::invalid_argument& e) {
      py::object error = py::handle(scene_error.ptr())(e.what());
      error.attr("key") = py::none();
      error.attr("value") = py::none();
      error.attr("source") = py::none();
      PyErr_SetObject(scene_error.ptr(), error.ptr());
    } catch (const NumericalFailure& e) {
      PyErr_SetString(numerical_error.ptr(), e.what());
    }
  });
}

}  // namespace cosmems::python
