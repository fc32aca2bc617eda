// Transient steps of frames through the stepper every transient run uses (MakeBeamStepper): the
// full-order linear Newmark step (average acceleration, factored once) and modal propagation of
// ten modes with the static correction, each timed per step with the model's free dofs and band.
// - the reference cantilever as a netlist (FrameModel, numbered in reverse Cuthill-McKee order)
//   against the same beam as a chain (BeamModel), in the same run;
// - the folded-flexure resonator against elements per member (10, and 125: 1000 elements in
//   all), with `x_realtime`, the simulated time per wall time at 20 steps per period of the
//   lowest mode (the modal path propagates every mode exactly at any step);
// - the cantilever chain at the same dofs, for the cost per step against dofs of both;
// - what each surface effect adds to a device's step (BM_DeviceEffectStep): the serpentine plate
//   of the scene `serpentine-pullin` (2 um over the substrate, 4 elements per segment, 846 dofs)
//   pushed down by 1 uN and stepped through the scene's forces (FrameSceneForces), with no
//   effect (the linear step) or one declared.
#include <string>
#include <vector>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "reference_beam.hpp"
#include "step_time.hpp"
#include "structure/test_frames.hpp"

namespace cosmems {
namespace {

constexpr int kModes = 10;

// One stepper of `path` for `model` under a unit load pattern `pattern` and the nonlinear
// `force` (or none), started at rest with the load on; its time step a twentieth of the lowest
// mode's period.
template <class Model>
struct Stepping {
  BeamStepperSetup setup;
  double time_step_s = 0.0;

  Stepping(const Model& model, TimePath path, const Eigen::VectorXd& pattern,
           NonlinearForce* force) {
    ModalOptions ten;
    ten.count = kModes;
    const ModalResult modes = SolveModal(model, ten);
    time_step_s = 1.0 / (20.0 * modes.modes.front().frequency_hz);
    StepperOptions options;
    options.path = path;
    options.modes = kModes;
    options.time_step = time_step_s;
    options.parameters = GeneralizedAlphaParameters::Newmark(0.25, 0.5);
    setup = MakeBeamStepper(model, options, pattern, force);
    const int n = model.FreeDofCount();
    if (setup.status == Status::kOk) {
      setup.status = setup.stepper->Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n),
                                               Eigen::VectorXd::Ones(1));
    }
  }
};

// Times the steps of `model` and sets the counters.
template <class Model>
void TimeSteps(benchmark::State& state, const Model& model, TimePath path,
               const Eigen::VectorXd& pattern, NonlinearForce* force = nullptr) {
  Stepping<Model> stepping(model, path, pattern, force);
  if (stepping.setup.status != Status::kOk) {
    state.SkipWithError("set-up failed");
    return;
  }
  BeamStepper& stepper = *stepping.setup.stepper;
  const Eigen::VectorXd s = Eigen::VectorXd::Ones(1);
  const double ns = bench::TimedLoop(state, [&] {
    const Status status = stepper.Step(s);
    benchmark::DoNotOptimize(status);
  });
  state.counters["dofs"] = model.FreeDofCount();
  state.counters["band"] = model.Stiffness().bandwidth();
  state.counters["x_realtime"] = stepping.time_step_s * 1e9 / ns;
}

// The reference cantilever (20 elements, series order 1) with a tip force: the netlist.
void BM_CantileverStep_Netlist(benchmark::State& state) {
  StructureDescription s;
  s.nodes.push_back({"root", {0, 0, 0}, AnchorOf(Support::kClamped)});
  s.nodes.push_back({"tip", {200e-6, 0, 0}, AnchorMask{}});
  s.members.push_back({0, 1, Material{169e9, 2330.0, 0.22}, RectangularSection{20e-6, 2e-6}, 20});
  const FrameModel model(s);
  FrameLoadCase tip;
  tip.points.push_back({1, -1, {0, -1e-7, 0}, {0, 0, 0}});
  TimeSteps(state, model, static_cast<TimePath>(state.range(0)), AssembleFrameLoads(model, tip));
}

// The same cantilever as the chain.
void BM_CantileverStep_Chain(benchmark::State& state) {
  const BeamModel<3> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  LoadCase tip;
  tip.points.push_back({200e-6, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  TimeSteps(state, model, static_cast<TimePath>(state.range(0)), AssembleLoads(model, tip));
}

void Paths(benchmark::internal::Benchmark* b) {
  b->ArgName("path");
  b->Arg(static_cast<int>(TimePath::kNewmarkFamily));
  b->Arg(static_cast<int>(TimePath::kModal));
}
BENCHMARK(BM_CantileverStep_Netlist)->Apply(Paths)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CantileverStep_Chain)->Apply(Paths)->Unit(benchmark::kMicrosecond);

// The folded flexure at range(1) elements per member, pulled along x at the shuttle.
void BM_FoldedFlexureStep(benchmark::State& state) {
  const FrameModel model(test::FoldedFlexure(100e-6, static_cast<int>(state.range(1))));
  FrameLoadCase pull;
  pull.points.push_back({-1, 2, {1e-6, 0, 0}, {0, 0, 0}});
  TimeSteps(state, model, static_cast<TimePath>(state.range(0)), AssembleFrameLoads(model, pull));
}
BENCHMARK(BM_FoldedFlexureStep)
    ->ArgNames({"path", "per_member"})
    ->ArgsProduct({{static_cast<int>(TimePath::kNewmarkFamily), static_cast<int>(TimePath::kModal)},
                   {2, 5, 10, 20, 40, 125}})
    ->Unit(benchmark::kMicrosecond);

// The cantilever chain of range(0) elements (series order 1) under a uniform load: the full
// step's cost against dofs beside the frame's.
void BM_ChainStep(benchmark::State& state) {
  const BeamModel<3> model(
      bench::ReferenceBeam(StructureKind::kCantilever, static_cast<int>(state.range(0)), 1));
  LoadCase uniform;
  uniform.distributed = Eigen::Vector3d(0, -1e-3, 0);
  TimeSteps(state, model, TimePath::kNewmarkFamily, AssembleLoads(model, uniform));
}
BENCHMARK(BM_ChainStep)
    ->Arg(10)
    ->Arg(40)
    ->Arg(100)
    ->Arg(300)
    ->Arg(1000)
    ->Unit(benchmark::kMicrosecond);

// The serpentine plate with the effects `sets` declare (its electrode off).
void BM_DeviceEffectStep(benchmark::State& state, std::vector<std::string> sets) {
  sets.insert(sets.end(), {"analysis.type=\"transient\"", "analysis.duration=1e-4",
                           "analysis.time_step=1e-7", "effects.electrostatic.enabled=false"});
  std::vector<SceneOverride> overrides;
  for (const std::string& set : sets) overrides.push_back(SceneOverride::Parse(set));
  const Scene scene = LoadScene("serpentine-pullin", overrides);
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  FrameSceneForces forces(model, scene);
  FrameLoadCase push;
  push.points.push_back({-1, 0, {0, -1e-6, 0}, {0, 0, 0}});
  TimeSteps(state, model, TimePath::kNewmarkFamily, AssembleFrameLoads(model, push),
            forces.all().Empty() ? nullptr : &forces.all());
}
BENCHMARK_CAPTURE(BM_DeviceEffectStep, none, {})->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DeviceEffectStep, casimir, {"effects.casimir.enabled=true"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DeviceEffectStep, van_der_waals, {"effects.van_der_waals.hamaker=1e-19"})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_DeviceEffectStep, squeeze_film, {"effects.squeeze_film.viscosity=1.81e-5"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
