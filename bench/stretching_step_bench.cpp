// One nonlinear Newmark step of a stretching microbridge (the reference section, 200 um,
// clamped-clamped), ringing at about half a thickness after a sudden midspan load: Newton on
// the consistent tangent, whose rank-one part is solved by Sherman-Morrison on the band.
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "reference_beam.hpp"
#include "step_extremes.hpp"

namespace cosmems {
namespace {

template <int Dim>
void BM_StretchingNewmarkStep(benchmark::State& state) {
  const BeamModel<Dim> model(
      bench::ReferenceBeam(StructureKind::kBridge, static_cast<int>(state.range(0)), 0));
  StretchingForce<Dim> force(model);
  LoadCase loads;
  loads.points.push_back({100e-6, Eigen::Vector3d(0, -1e-4, 0), Eigen::Vector3d::Zero()});
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  const double period = 2.3e-6 / model.units().time;  // f1 = 438 kHz
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, force,
                                        GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                        period / 20);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.FreeDofCount());
  if (integrator.Initialize(zero, zero, f) != Status::kOk) {
    state.SkipWithError("initialisation failed");
    return;
  }
  long iterations = 0, evaluations = 0, factorizations = 0, steps = 0;
  auto step = [&] {
    const Status status = integrator.Step(f);
    benchmark::DoNotOptimize(status);
    iterations += integrator.last_stats().iterations;
    evaluations += integrator.last_stats().evaluations;
    factorizations += integrator.last_stats().factorizations;
    ++steps;
  };
  for (auto _ : state) step();
  state.counters["newton_per_step"] = static_cast<double>(iterations) / static_cast<double>(steps);
  state.counters["residuals_per_step"] =
      static_cast<double>(evaluations) / static_cast<double>(steps);
  state.counters["factor_per_step"] =
      static_cast<double>(factorizations) / static_cast<double>(steps);
  bench::RecordStepExtremes(state, step);
  state.counters["dofs"] = model.FreeDofCount();
}

BENCHMARK(BM_StretchingNewmarkStep<2>)->Arg(10)->Arg(20)->Arg(40)->ArgName("elements");
BENCHMARK(BM_StretchingNewmarkStep<3>)->Arg(40)->ArgName("elements");

}  // namespace
}  // namespace cosmems
