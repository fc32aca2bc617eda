#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
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

// What cosmems.sweep() passes on: the CLI's options, named as there.
struct SweepArguments {
  std::string scene;
  std::vector<std::string> sets;
  std::vector<std::pair<std::string, std::string>> vary;
  std::vector<std::string> specs;
  std::vector<std::string> plots;
  std::optional<std::string> method;
  std::optional<std::int64_t> samples;
  std::optional<std::uint64_t> seed;
  int threads = 0;
  std::optional<std::string> shard;
  std::string out;
};

// The summary JSON and the rows as one JSON array.
std::pair<std::string, std::string> Sweep(const SweepArguments& arguments) {
  internal::SweepRequest request;
  request.scene = arguments.scene;
  request.sets = arguments.sets;
  request.vary = arguments.vary;
  request.specs = arguments.specs;
  request.plots = arguments.plots;
  request.method = arguments.method;
  request.samples = arguments.samples;
  request.seed = arguments.seed;
  request.threads = arguments.threads;
  if (arguments.shard) request.SetShard(*arguments.shard);
  request.out = arguments.out;
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
  py::class_<SweepArguments>(m, "SweepArguments")
      .def(py::init<>())
      .def_readwrite("scene", &SweepArguments::scene)
      .def_readwrite("sets", &SweepArguments::sets)
      .def_readwrite("vary", &SweepArguments::vary)
      .def_readwrite("specs", &SweepArguments::specs)
      .def_readwrite("plots", &SweepArguments::plots)
      .def_readwrite("method", &SweepArguments::method)
      .def_readwrite("samples", &SweepArguments::samples)
      .def_readwrite("seed", &SweepArguments::seed)
      .def_readwrite("threads", &SweepArguments::threads)
      .def_readwrite("shard", &SweepArguments::shard)
      .def_readwrite("out", &SweepArguments::out);
  m.def("sweep", &Sweep, py::arg("arguments"), py::call_guard<py::gil_scoped_release>(),
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
