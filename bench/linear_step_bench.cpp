// Per-step cost of the linear fast path (factor once, back-solve per step; average
// acceleration, undamped) against element count, for each factorisation: the measurements
// behind SpdSolver's automatic choice.
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "reference_beam.hpp"
#include "step_extremes.hpp"

namespace cosmems {
namespace {

template <int Dim, SpdSolverKind kSolver>
void BM_LinearNewmarkStep(benchmark::State& state) {
  const BeamModel<Dim> model(
      bench::ReferenceBeam(StructureKind::kCantilever, static_cast<int>(state.range(0)), 0));
  const int n = model.FreeDofCount();
  const double period = 14.5e-6 / model.units().time;  // f1 = 68.8 kHz
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {},
                                     GeneralizedAlphaParameters::Newmark(0.25, 0.5), period / 20,
                                     kSolver);
  const Eigen::VectorXd f = Eigen::VectorXd::Constant(n, 1e-4);
  if (integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f) != Status::kOk) {
    state.SkipWithError("initialisation failed");
    return;
  }
  auto step = [&] {
    const Status status = integrator.Step(f);
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(integrator.displacement().data());
  };
  for (auto _ : state) step();
  bench::RecordStepExtremes(state, step);
  state.counters["dofs"] = n;
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

}  // namespace
}  // namespace cosmems
