// One haptic tick: 1 ms of simulated time of the 20-element reference cantilever (f1 = 68.8 kHz,
// about 69 periods), by the modal path (4 modes, exact propagation, 1 us steps so f1 is sampled
// 14 times a period) and by the full-order band path (20 steps a period of f1). The load is
// updated every step, as a stylus would update it.
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/modal_model.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

constexpr double kTick = 1e-3;

LoadCase TipForce() {
  LoadCase loads;
  loads.points.push_back({200e-6, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  return loads;
}

void BM_HapticTickModal(benchmark::State& state) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  const Eigen::MatrixXd pattern = AssembleLoads(model, TipForce());
  ModalOptions options;
  options.count = 4;
  const ModalModel modal =
      MakeModalModel(model, SolveModal(model, options), DampingModel::QualityFactor(100));
  const double dt = 1e-6;
  ModalPropagator propagator(modal.coordinates, modal.shapes, pattern,
                             modal.ResidualFlexibility(model, pattern), dt / model.units().time);
  Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(modal.shapes.cols());
  propagator.Initialize(q0, q0, s);
  const int tip = model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy);
  const int steps = static_cast<int>(kTick / dt);
  double t = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < steps; ++i) {
      t += dt;
      s[0] = std::sin(2 * kPi * 50.0 * t);  // a hand moving at 50 Hz
      if (propagator.Step(s) != Status::kOk) state.SkipWithError("step failed");
    }
    benchmark::DoNotOptimize(propagator.DisplacementAt(tip));
  }
  state.counters["steps"] = steps;
  state.counters["realtime_factor"] =
      benchmark::Counter(kTick * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_HapticTickModal)->Unit(benchmark::kMicrosecond);

void BM_HapticTickFullBand(benchmark::State& state) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 0));
  const Eigen::VectorXd pattern = AssembleLoads(model, TipForce());
  const double dt = 1.0 / (68.8e3 * 20);
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {},
                                     GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                     dt / model.units().time, SpdSolverKind::kBand);
  const int n = model.FreeDofCount();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  if (integrator.Initialize(f, f, f) != Status::kOk) state.SkipWithError("initialisation failed");
  const int steps = static_cast<int>(kTick / dt);
  double t = 0.0;
  for (auto _ : state) {
    for (int i = 0; i < steps; ++i) {
      t += dt;
      f = pattern * std::sin(2 * kPi * 50.0 * t);
      if (integrator.Step(f) != Status::kOk) state.SkipWithError("step failed");
    }
    benchmark::DoNotOptimize(integrator.displacement().data());
  }
  state.counters["steps"] = steps;
}
BENCHMARK(BM_HapticTickFullBand)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
