#pragma once

// The paper's reference silicon beams for every benchmark, as BeamModel's description and as the
// one-member netlist every front end builds (StraightBeam), and the element counts swept.

#include <benchmark/benchmark.h>

#include "cosmems/cosmems.hpp"

namespace cosmems::bench {

inline BeamDescription ReferenceBeam(StructureKind kind, int elements, int order) {
  return MakeStructure(kind, 200e-6, Material{169e9, 2330.0, 0.22}, RectangularSection{20e-6, 2e-6},
                       elements, order);
}

/// The same beam as its one-member netlist: planar (u_x, u_y, r_z) or spatial.
inline StructureDescription ReferenceChain(StructureKind kind, int elements, int order,
                                           bool planar) {
  StraightBeamDesign d;
  d.bridge = kind == StructureKind::kBridge;
  d.elements = elements;
  d.series_order = order;
  d.planar = planar;
  return StraightBeam(d);
}

/// The reference cantilever's tip (node 1 of its netlist) under a force along -y [N].
inline FrameLoadCase ChainTipForce(double force_n) {
  FrameLoadCase loads;
  loads.points.push_back({1, -1, Eigen::Vector3d(0.0, -force_n, 0.0), Eigen::Vector3d::Zero()});
  return loads;
}

/// Element counts 2 ... 200.
inline void ElementCounts(benchmark::internal::Benchmark* b) {
  for (int n : {2, 5, 10, 20, 50, 100, 200}) b->Arg(n);
}

}  // namespace cosmems::bench
