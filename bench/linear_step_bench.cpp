// Per-step cost of the linear fast path (factor once, back-solve per step;
// average acceleration, undamped) against element count, for each
// factorisation: the measurements behind SpdSolver's automatic choice. The band
// runs also report their operation count and its time on this machine
// (bench/flop_rate.hpp) and, up to 100 elements, the time of the same step with
// dense LLT (`dense_ns`, `x_dense`): the yardsticks of a step at the speed of
// its arithmetic. Each runs on BeamModel<Dim> and on the same cantilever's one-member netlist
// (FrameModel; planar for Dim 2), what every front end builds (`Chain` in the name).
#include <algorithm>

#include "cosmems/time/linear_newmark_integrator.hpp"
#include "flop_rate.hpp"
#include "reference_beam.hpp"
#include "step_extremes.hpp"
#include "step_time.hpp"

namespace cosmems {
namespace {

// The integrator of the reference cantilever's step by `solver`, started under
// a uniform load.
template <class Model>
LinearNewmarkIntegrator MakeStep(const Model& model, SpdSolverKind solver,
                                 const Eigen::VectorXd& f) {
  const double period = 14.5e-6 / model.units().time;  // f1 = 68.8 kHz
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {},
                                     GeneralizedAlphaParameters::Newmark(0.25, 0.5), period / 20,
                                     solver);
  const int n = model.FreeDofCount();
  (void)integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f);
  return integrator;
}

// One step of `integrator` to the load f, kept from being optimised away.
auto Stepping(LinearNewmarkIntegrator& integrator, const Eigen::VectorXd& f) {
  return [&integrator, &f] {
    const Status status = integrator.Step(f);
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(integrator.displacement().data());
  };
}

// The band step's floating-point operations per unknown, as the code runs them:
// the row product with K over the padded band (2 (2W + 1)), the two sweeps (4W)
// and the pivots (1), Newmark's updates of d, v and the next product's vector
// (6 + 4 + 4). Average acceleration without damping needs no product with M.
double BandStepFlops(int n, int bandwidth) {
  return n * (2.0 * (2 * bandwidth + 1) + 4.0 * bandwidth + 1.0 + 14.0);
}

template <SpdSolverKind kSolver, class Model>
void TimeTheStep(benchmark::State& state, const Model& model) {
  const int n = model.FreeDofCount();
  const Eigen::VectorXd f = Eigen::VectorXd::Constant(n, 1e-4);
  LinearNewmarkIntegrator integrator = MakeStep(model, kSolver, f);
  if (integrator.info() != Status::kOk) {
    state.SkipWithError("initialisation failed");
    return;
  }
  auto step = Stepping(integrator, f);
  const double step_ns = bench::TimedLoop(state, step);
  bench::RecordStepExtremes(state, step);
  state.counters["dofs"] = n;
  if (kSolver != SpdSolverKind::kBand) return;
  bench::RecordArithmetic(state, BandStepFlops(n, model.Stiffness().bandwidth()), step_ns);
  if (state.range(0) > 100) return;
  LinearNewmarkIntegrator dense = MakeStep(model, SpdSolverKind::kDense, f);
  const long steps = std::max<long>(1000, static_cast<long>(state.iterations()) / 4);
  const double dense_ns = bench::TimeSteps(steps, Stepping(dense, f));
  state.counters["dense_ns"] = dense_ns;
  state.counters["x_dense"] = step_ns / dense_ns;
}

template <int Dim, SpdSolverKind kSolver>
void BM_LinearNewmarkStep(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  TimeTheStep<kSolver>(
      state, BeamModel<Dim>(bench::ReferenceBeam(StructureKind::kCantilever, elements, 0)));
}

template <int Dim, SpdSolverKind kSolver>
void BM_LinearNewmarkStepChain(benchmark::State& state) {
  const int elements = static_cast<int>(state.range(0));
  TimeTheStep<kSolver>(
      state, FrameModel(bench::ReferenceChain(StructureKind::kCantilever, elements, 0, Dim == 2)));
}

void Small(benchmark::internal::Benchmark* b) {
  for (int n : {1, 2, 3, 4, 5, 10, 20, 50, 100}) b->Arg(n);
  b->ArgName("elements");
}
void Large(benchmark::internal::Benchmark* b) {
  for (int n : {1, 2, 3, 4, 5, 10, 20, 50, 100, 200, 500}) b->Arg(n);
  b->ArgName("elements");
}

BENCHMARK(BM_LinearNewmarkStep<2, SpdSolverKind::kDense>)->Apply(Small);
BENCHMARK(BM_LinearNewmarkStep<2, SpdSolverKind::kBand>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStep<2, SpdSolverKind::kCholmod>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStep<3, SpdSolverKind::kDense>)->Apply(Small);
BENCHMARK(BM_LinearNewmarkStep<3, SpdSolverKind::kBand>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStep<3, SpdSolverKind::kCholmod>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStepChain<2, SpdSolverKind::kDense>)->Apply(Small);
BENCHMARK(BM_LinearNewmarkStepChain<2, SpdSolverKind::kBand>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStepChain<2, SpdSolverKind::kCholmod>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStepChain<3, SpdSolverKind::kDense>)->Apply(Small);
BENCHMARK(BM_LinearNewmarkStepChain<3, SpdSolverKind::kBand>)->Apply(Large);
BENCHMARK(BM_LinearNewmarkStepChain<3, SpdSolverKind::kCholmod>)->Apply(Large);

}  // namespace
}  // namespace cosmems
