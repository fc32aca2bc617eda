// Element matrix evaluation: one element's K_L and mass terms M_0 ... M_2k, planar and spatial,
// and the one-off construction of the power-series bases of an order.
#include "reference_beam.hpp"

namespace cosmems {
namespace {

ElementProperties Properties() {
  return BeamModel<2>(bench::ReferenceBeam(StructureKind::kCantilever, 20, 0))
      .elements()[0]
      .properties();
}

template <int Dim>
void BM_ElementMatrices(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  const FrameBases bases(order);
  const FrameElement<Dim> element(Properties());
  for (auto _ : state) {
    auto k = element.Stiffness(bases);
    benchmark::DoNotOptimize(k);
    for (int j = 0; j <= order; ++j) {
      auto m = element.Mass(bases, j);
      benchmark::DoNotOptimize(m);
    }
  }
}
BENCHMARK(BM_ElementMatrices<2>)->ArgName("order")->DenseRange(0, 3);
BENCHMARK(BM_ElementMatrices<3>)->ArgName("order")->DenseRange(0, 3);

void BM_PowerSeriesBases(benchmark::State& state) {
  const int order = static_cast<int>(state.range(0));
  for (auto _ : state) {
    FrameBases bases(order);
    benchmark::DoNotOptimize(bases);
  }
}
BENCHMARK(BM_PowerSeriesBases)->ArgName("order")->DenseRange(0, 3);

}  // namespace
}  // namespace cosmems
