// Per-step cost of exact modal propagation (one load pattern, uy at the tip read every step)
// against the number of modes, and its multiple of the time its arithmetic takes on this machine:
// (14 + 2m) k flops for k modes and m patterns, and 2 (k + m) to read uy (bench/flop_rate.hpp).
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/time/modal_model.hpp"
#include "flop_rate.hpp"
#include "reference_beam.hpp"
#include "step_extremes.hpp"
#include "step_time.hpp"

namespace cosmems {
namespace {

void BM_ModalStep(benchmark::State& state) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  LoadCase loads;
  loads.points.push_back({200e-6, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  const Eigen::MatrixXd pattern = AssembleLoads(model, loads);
  ModalOptions options;
  options.count = static_cast<int>(state.range(0));
  const ModalModel modal =
      MakeModalModel(model, SolveModal(model, options), DampingModel::QualityFactor(100));
  ModalPropagator propagator(modal.coordinates, modal.shapes, pattern,
                             modal.ResidualFlexibility(model, pattern), 1e-6 / model.units().time);
  Eigen::VectorXd s = Eigen::VectorXd::Ones(1);
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(modal.shapes.cols());
  propagator.Initialize(q0, q0, s);
  const int tip = model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy);
  auto step = [&] {
    s[0] = -s[0];
    const Status status = propagator.Step(s);
    benchmark::DoNotOptimize(status);
    benchmark::DoNotOptimize(propagator.DisplacementAt(tip));
  };
  const double step_ns = bench::TimedLoop(state, step);
  bench::RecordStepExtremes(state, step);
  const double k = static_cast<double>(modal.shapes.cols());
  bench::RecordArithmetic(state, (14.0 + 2.0) * k + 2.0 * (k + 1.0), step_ns);
}
BENCHMARK(BM_ModalStep)->ArgName("modes")->Arg(1)->Arg(2)->Arg(4)->Arg(8)->Arg(16);

}  // namespace
}  // namespace cosmems
