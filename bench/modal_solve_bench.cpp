// Modal analysis of the reference cantilever, the four lowest modes, against element count:
// order 0 (generalised eigenproblem) and order 1 (polynomial eigenproblem).
#include "reference_beam.hpp"

namespace cosmems {
namespace {

template <int Dim>
void BM_ModalSolve(benchmark::State& state) {
  const int order = static_cast<int>(state.range(1));
  const BeamModel<Dim> model(
      bench::ReferenceBeam(StructureKind::kCantilever, static_cast<int>(state.range(0)), order));
  ModalOptions options;
  options.count = 4;
  int iterations = 0;
  for (auto _ : state) {
    ModalResult r = SolveModal(model, options);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r);
  }
  state.counters["dofs"] = model.FreeDofCount();
  state.counters["sweeps"] = iterations;
}

void Sweep(benchmark::internal::Benchmark* b) {
  b->ArgNames({"elements", "order"});
  for (int order : {0, 1}) {
    for (int n : {2, 5, 10, 20, 50, 100, 200}) b->Args({n, order});
  }
}
BENCHMARK(BM_ModalSolve<2>)->Apply(Sweep)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ModalSolve<3>)->Apply(Sweep)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
