#pragma once

// The paper's reference silicon beams for every benchmark, and the element counts swept.

#include <benchmark/benchmark.h>

#include "cosmems/cosmems.hpp"

namespace cosmems::bench {

inline BeamDescription ReferenceBeam(StructureKind kind, int elements, int order) {
  return MakeStructure(kind, 200e-6, Material{169e9, 2330.0, 0.22}, RectangularSection{20e-6, 2e-6},
                       elements, order);
}

/// Element counts 2 ... 200.
inline void ElementCounts(benchmark::internal::Benchmark* b) {
  for (int n : {2, 5, 10, 20, 50, 100, 200}) b->Arg(n);
}

}  // namespace cosmems::bench
