// Frames: static and modal solves of the folded-flexure resonator (structure/test_frames.hpp)
// against elements per member, the serpentine plate's pull-in against elements per segment, and the
// reference cantilever as a netlist (FrameModel, numbered node by node in reverse Cuthill-McKee
// order) against the same beam as a chain (BeamModel, numbered field by field), in the same run.
#include "reference_beam.hpp"
#include "structure/test_frames.hpp"

namespace cosmems {
namespace {

// Elements per member of the folded flexure: 2 ... 40.
void MemberElements(benchmark::internal::Benchmark* b) {
  for (int n : {2, 5, 10, 20, 40}) b->Arg(n);
}

// Times solve() over the loop; the model's free dofs and band as counters.
template <class Model, class Solve>
void TimeSolve(benchmark::State& state, const Model& model, Solve solve) {
  for (auto _ : state) {
    auto result = solve();
    benchmark::DoNotOptimize(result);
  }
  state.counters["dofs"] = model.FreeDofCount();
  state.counters["band"] = model.Stiffness().bandwidth();
}

// The folded flexure at range(0) elements per member: factorisation (band Cholesky over the
// reverse Cuthill-McKee numbering, or CHOLMOD's own ordering), loads, back-solve and recovery.
template <SpdSolverKind kSolver>
void BM_FoldedFlexureStatic(benchmark::State& state) {
  const FrameModel model(test::FoldedFlexure(100e-6, static_cast<int>(state.range(0))));
  FrameLoadCase pull;
  pull.points.push_back({-1, 2, {1e-6, 0, 0}, {0, 0, 0}});
  TimeSolve(state, model, [&] { return SolveFrameStatic(model, pull, kSolver); });
}
BENCHMARK(BM_FoldedFlexureStatic<SpdSolverKind::kBand>)
    ->Apply(MemberElements)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FoldedFlexureStatic<SpdSolverKind::kCholmod>)
    ->Apply(MemberElements)
    ->Unit(benchmark::kMicrosecond);

// The ten lowest modes at range(0) elements per member (series order 1).
void BM_FoldedFlexureModal(benchmark::State& state) {
  const FrameModel model(test::FoldedFlexure(100e-6, static_cast<int>(state.range(0))));
  ModalOptions options;
  options.count = 10;
  TimeSolve(state, model, [&] { return SolveFrameModal(model, options); });
}
BENCHMARK(BM_FoldedFlexureModal)->Apply(MemberElements)->Unit(benchmark::kMillisecond);

// The pull-in of the serpentine-suspended plate over an electrode of its size at range(0)
// elements per segment: the fold traced by displacement control of the plate (SolveFramePullIn,
// the shape at the fold recovered), with its error against the parallel plate's
// sqrt(8 k g^3 / (27 eps0 A)) on the springs' Castigliano stiffness as a counter.
void BM_SerpentinePullIn(benchmark::State& state) {
  SerpentineDesign design;
  design.material = test::Poly();
  design.elements = static_cast<int>(state.range(0));
  const FrameModel model(Serpentine(design));
  FramePullInOptions options;
  options.electrodes.gap = 2e-6;
  options.electrodes.electrodes = {Electrode{{-50e-6, 50e-6}, {-50e-6, 50e-6}}};
  FramePullInResult result;
  TimeSolve(state, model, [&] { return result = SolveFramePullIn(model, options); });
  const double exact =
      std::sqrt(8.0 * design.Stiffness() * 8e-18 / (27.0 * kVacuumPermittivity * 1e-8));
  state.counters["voltage_error"] = std::abs(result.fold.voltage_v / exact - 1.0);
  state.counters["solves"] = result.fold.solves;
}
BENCHMARK(BM_SerpentinePullIn)->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Unit(benchmark::kMillisecond);

// Model assembly of the folded flexure (members rotated, bodies eliminated, numbering).
void BM_FoldedFlexureAssembly(benchmark::State& state) {
  const StructureDescription s = test::FoldedFlexure(100e-6, static_cast<int>(state.range(0)));
  for (auto _ : state) {
    FrameModel model(s);
    benchmark::DoNotOptimize(model);
  }
}
BENCHMARK(BM_FoldedFlexureAssembly)->Arg(10)->Unit(benchmark::kMicrosecond);

// The reference cantilever under a tip force, 20 elements: as a netlist and as a chain.
StructureDescription NetlistCantilever() {
  StructureDescription s;
  s.nodes.push_back({"root", {0, 0, 0}, AnchorOf(Support::kClamped)});
  s.nodes.push_back({"tip", {200e-6, 0, 0}, AnchorMask{}});
  s.members.push_back({0, 1, Material{169e9, 2330.0, 0.22}, RectangularSection{20e-6, 2e-6}, 20});
  return s;
}

ModalOptions FourModes() {
  ModalOptions options;
  options.count = 4;
  return options;
}

void BM_CantileverStatic_Netlist(benchmark::State& state) {
  const FrameModel model(NetlistCantilever());
  FrameLoadCase loads;
  loads.points.push_back({1, -1, {0, -1e-7, 0}, {0, 0, 0}});
  TimeSolve(state, model, [&] { return SolveFrameStatic(model, loads); });
}
BENCHMARK(BM_CantileverStatic_Netlist)->Unit(benchmark::kMicrosecond);

void BM_CantileverStatic_Chain(benchmark::State& state) {
  const BeamModel<3> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  LoadCase loads;
  loads.points.push_back({200e-6, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  TimeSolve(state, model, [&] { return SolveStatic(model, loads); });
}
BENCHMARK(BM_CantileverStatic_Chain)->Unit(benchmark::kMicrosecond);

void BM_CantileverModal_Netlist(benchmark::State& state) {
  const FrameModel model(NetlistCantilever());
  TimeSolve(state, model, [&] { return SolveFrameModal(model, FourModes()); });
}
BENCHMARK(BM_CantileverModal_Netlist)->Unit(benchmark::kMicrosecond);

void BM_CantileverModal_Chain(benchmark::State& state) {
  const BeamModel<3> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  TimeSolve(state, model, [&] { return SolveModal(model, FourModes()); });
}
BENCHMARK(BM_CantileverModal_Chain)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
