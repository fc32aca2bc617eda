// Linear static solve of the reference cantilever under a tip force (loads, factorisation,
// back-solve), band Cholesky against CHOLMOD, and the back-solve alone.
#include "reference_beam.hpp"

namespace cosmems {
namespace {

LoadCase TipForce() {
  LoadCase loads;
  loads.points.push_back({200e-6, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  return loads;
}

template <int Dim, LinearSolverKind kSolver>
void BM_StaticSolve(benchmark::State& state) {
  const BeamModel<Dim> model(
      bench::ReferenceBeam(StructureKind::kCantilever, static_cast<int>(state.range(0)), 1));
  const LoadCase loads = TipForce();
  for (auto _ : state) {
    StaticSolution s = SolveStatic(model, loads, kSolver);
    benchmark::DoNotOptimize(s);
  }
  state.counters["dofs"] = model.FreeDofCount();
}
BENCHMARK(BM_StaticSolve<2, LinearSolverKind::kBand>)
    ->Apply(bench::ElementCounts)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticSolve<3, LinearSolverKind::kBand>)
    ->Apply(bench::ElementCounts)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_StaticSolve<3, LinearSolverKind::kCholmod>)
    ->Apply(bench::ElementCounts)
    ->Unit(benchmark::kMicrosecond);

template <int Dim>
void BM_BandBackSolve(benchmark::State& state) {
  const BeamModel<Dim> model(
      bench::ReferenceBeam(StructureKind::kCantilever, static_cast<int>(state.range(0)), 1));
  const BandCholesky cholesky(model.Stiffness());
  const Eigen::VectorXd f = AssembleLoads(model, TipForce());
  Eigen::VectorXd x = f;
  for (auto _ : state) {
    x = f;
    cholesky.SolveInPlace(x);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_BandBackSolve<2>)->Apply(bench::ElementCounts)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BandBackSolve<3>)->Apply(bench::ElementCounts)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
