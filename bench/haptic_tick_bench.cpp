// One haptic tick: 1 ms of simulated time of the 20-element reference cantilever (f1 = 68.8 kHz,
// about 69 periods), by the modal path (4 modes, exact propagation, 1 us steps so f1 is sampled
// 14 times a period) and by the full-order band path (20 steps a period of f1). The load is
// updated every step, as a stylus would update it. Each runs on BeamModel<2> and on the planar
// one-member netlist every front end builds (`Chain` in the name).
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/modal_model.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

constexpr double kTick = 1e-3;

// The tip force's load pattern (0.1 uN down) and the tip's u_y, on either model.
Eigen::VectorXd TipPattern(const BeamModel<2>& model) {
  LoadCase loads;
  loads.points.push_back({200e-6, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  return AssembleLoads(model, loads);
}
Eigen::VectorXd TipPattern(const FrameModel& model) {
  return AssembleFrameLoads(model, bench::ChainTipForce(1e-7));
}
int TipDof(const BeamModel<2>& model) {
  return model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy);
}
int TipDof(const FrameModel& model) { return model.CarrierDof(model.mesh().nodes[1].carrier, 1); }

template <class Model>
void TimeTheModalTick(benchmark::State& state, const Model& model) {
  const Eigen::MatrixXd pattern = TipPattern(model);
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
  const int tip = TipDof(model);
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

void BM_HapticTickModal(benchmark::State& state) {
  TimeTheModalTick(state, BeamModel<2>(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1)));
}
BENCHMARK(BM_HapticTickModal)->Unit(benchmark::kMicrosecond);

void BM_HapticTickModalChain(benchmark::State& state) {
  TimeTheModalTick(state,
                   FrameModel(bench::ReferenceChain(StructureKind::kCantilever, 20, 1, true)));
}
BENCHMARK(BM_HapticTickModalChain)->Unit(benchmark::kMicrosecond);

template <class Model>
void TimeTheFullBandTick(benchmark::State& state, const Model& model) {
  const Eigen::VectorXd pattern = TipPattern(model);
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

void BM_HapticTickFullBand(benchmark::State& state) {
  TimeTheFullBandTick(state, BeamModel<2>(bench::ReferenceBeam(StructureKind::kCantilever, 20, 0)));
}
BENCHMARK(BM_HapticTickFullBand)->Unit(benchmark::kMicrosecond);

void BM_HapticTickFullBandChain(benchmark::State& state) {
  TimeTheFullBandTick(state,
                      FrameModel(bench::ReferenceChain(StructureKind::kCantilever, 20, 0, true)));
}
BENCHMARK(BM_HapticTickFullBandChain)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
