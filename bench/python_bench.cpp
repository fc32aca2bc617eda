// What the Python face costs (doc/python.md, "Measured"): a Newmark step called from a Python
// loop against the same step in C++ (ModelStepper, which the module wraps, and the bare
// integrator under it), and a sweep through cosmems.sweep against the CLI's RunSweep. Python
// runs embedded; it imports the build's package (COSMEMS_PYTHON_DIR).
#include <benchmark/benchmark.h>
#include <pybind11/embed.h>

#include <memory>
#include <sstream>
#include <string>

#include "cosmems/scene/scene_loader.hpp"
#include "model_stepper.hpp"
#include "sweep_runner.hpp"

namespace py = pybind11;

namespace cosmems {
namespace {

constexpr int kStepsPerCall = 1000;

py::scoped_interpreter& Interpreter() {
  static py::scoped_interpreter interpreter;
  static const bool path = [] {
    py::module_::import("sys").attr("path").attr("insert")(0, COSMEMS_PYTHON_DIR);
    return true;
  }();
  (void)path;
  return interpreter;
}

std::shared_ptr<python::SceneModel> Cantilever(int elements) {
  return python::SceneModel::Make(LoadScene(
      "cantilever", {SceneOverride::Parse("model.elements=" + std::to_string(elements))}));
}

void BM_StepIntegrator(benchmark::State& state) {
  const auto model = Cantilever(static_cast<int>(state.range(0)));
  LinearNewmarkIntegrator integrator(model->Mass(0), model->Stiffness(), {},
                                     GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                     1e-7 / model->units().time);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model->size());
  // The scene's tip force in internal units.
  const Eigen::VectorXd f = model->loads_si().cwiseProduct(model->dof_scale()) /
                            (model->units().force * model->units().length);
  (void)integrator.Initialize(zero, zero, zero);
  for (auto _ : state) benchmark::DoNotOptimize(integrator.Step(f));
}

void BM_StepCpp(benchmark::State& state) {
  const auto model = Cantilever(static_cast<int>(state.range(0)));
  python::ModelStepper stepper(model, 1e-7, GeneralizedAlphaParameters::Newmark(0.25, 0.5), {});
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model->size());
  const Eigen::VectorXd& f = model->loads_si();  // the scene's tip force
  (void)stepper.Initialize(zero, zero, zero);
  for (auto _ : state) benchmark::DoNotOptimize(stepper.Step(f));
}

void BM_StepPython(benchmark::State& state) {
  Interpreter();
  py::dict scope;
  scope["elements"] = state.range(0);
  py::exec(R"(
import numpy as np
import cosmems
model = cosmems.Scene("cantilever").set("model.elements", elements).model()
stepper = model.newmark(1e-7)
zero = np.zeros(model.size)
f = model.loads()
stepper.initialize(zero, zero, zero)
def run(n):
    step = stepper.step
    for _ in range(n):
        step(f)
)",
           scope);
  const py::object run = scope["run"];
  for (auto _ : state) run(kStepsPerCall);
  state.SetItemsProcessed(state.iterations() * kStepsPerCall);  // a step: 1 / items_per_second
}

#define COSMEMS_STEP_SIZES ArgName("elements")->Arg(20)->Arg(200)
BENCHMARK(BM_StepIntegrator)->COSMEMS_STEP_SIZES;
BENCHMARK(BM_StepCpp)->COSMEMS_STEP_SIZES;
BENCHMARK(BM_StepPython)->COSMEMS_STEP_SIZES->Unit(benchmark::kMillisecond);

// The README's pull-in map at 10 x 10 (100 pull-in analyses), on one thread.
const char* const kLengths = "structure.length=100e-6:300e-6:10";
const char* const kGaps = "structure.gap=1e-6:3e-6:10";

void BM_SweepCli(benchmark::State& state) {
  internal::SweepRequest request;
  request.scene = "cantilever-pullin";
  request.vary = {internal::SweepRequest::SplitVary(kLengths),
                  internal::SweepRequest::SplitVary(kGaps)};
  request.threads = 1;
  request.json = true;
  for (auto _ : state) {
    std::ostringstream out, err;
    if (internal::RunSweep(request, out, err, false) != 0) state.SkipWithError("sweep failed");
  }
}

void BM_SweepPython(benchmark::State& state) {
  Interpreter();
  py::dict scope;
  py::exec(R"(
import cosmems
def run():
    return cosmems.sweep("cantilever-pullin", threads=1,
                         vary={"structure.length": "100e-6:300e-6:10",
                               "structure.gap": "1e-6:3e-6:10"})
)",
           scope);
  const py::object run = scope["run"];
  for (auto _ : state) run();
}

BENCHMARK(BM_SweepCli)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SweepPython)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace cosmems
