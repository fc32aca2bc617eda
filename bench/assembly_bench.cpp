// Model set-up: element matrices of every element scattered into band storage (K_L and
// M_0 ... M_2k), against element count.
#include "reference_beam.hpp"

namespace cosmems {
namespace {

template <int Dim>
void BM_Assembly(benchmark::State& state) {
  const BeamDescription beam =
      bench::ReferenceBeam(StructureKind::kCantilever, static_cast<int>(state.range(0)), 1);
  for (auto _ : state) {
    BeamModel<Dim> model(beam);
    benchmark::DoNotOptimize(model);
  }
  state.counters["dofs"] = BeamModel<Dim>(beam).FreeDofCount();
}
BENCHMARK(BM_Assembly<2>)->Apply(bench::ElementCounts)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Assembly<3>)->Apply(bench::ElementCounts)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
