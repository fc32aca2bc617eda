// Per-step cost of the touchdown (contact, stiction and the Casimir force on the 20-element
// reference cantilever, a 6 uN tip force swinging at 5 kHz: approach, impact, sticking, release
// under load, over and over) on the two paths at the scene's 0.2 us step: modal propagation with
// the force held over each step (NonlinearModalIntegrator, 4 to 16 modes) against the full
// model by generalised-alpha (rho_inf = 0.6, as the cantilever-touchdown scene). A step whose
// Newton fails stops the run with an error, so every figure is of steps that were solved.
#include <cmath>

#include "reference_beam.hpp"
#include "step_extremes.hpp"

namespace cosmems {
namespace {

constexpr double kGap = 2e-6, kSeparation = 2e-8, kStep = 0.2e-6, kFrequency = 5e3;

using TouchdownForces = ForceTuple<SubstrateContact<2>, GapForce<2, CasimirPressure>>;

TouchdownForces MakeForces(const BeamModel<2>& model) {
  ContactOptions contact;
  contact.gap = kGap;
  contact.separation = kSeparation;
  contact.stiction = true;
  contact.adhesion_energy = 0.02;
  return TouchdownForces(
      SubstrateContact<2>(model, contact),
      GapForce<2, CasimirPressure>(model, CasimirPressure{},
                                   GapSpan{kGap, 0.0, 200e-6}.WithSeparation(kSeparation)));
}

Eigen::VectorXd TipForce(const BeamModel<2>& model) {
  LoadCase loads;
  loads.points.push_back({200e-6, Eigen::Vector3d(0, -6e-6, 0), Eigen::Vector3d::Zero()});
  return AssembleLoads(model, loads);
}

// Runs `step(amplitude)` over the swinging force; a failed step ends the benchmark. The mean
// Newton iterations (corrections), residual evaluations and factorisations a step go beside the
// times.
template <typename Integrator, typename Step>
void RunTouchdown(benchmark::State& state, const Integrator& integrator, Step&& step) {
  long i = 0, iterations = 0, evaluations = 0, factorizations = 0;
  auto next = [&] {
    ++i;
    const Status status = step(std::sin(2.0 * kPi * kFrequency * kStep * static_cast<double>(i)));
    if (status != Status::kOk) state.SkipWithError("a step failed");
    iterations += integrator.last_stats().iterations;
    evaluations += integrator.last_stats().evaluations;
    factorizations += integrator.last_stats().factorizations;
  };
  for (auto _ : state) next();
  state.counters["iterations"] = static_cast<double>(iterations) / static_cast<double>(i);
  state.counters["residuals"] = static_cast<double>(evaluations) / static_cast<double>(i);
  state.counters["factorizations"] = static_cast<double>(factorizations) / static_cast<double>(i);
  bench::RecordStepExtremes(state, next);
}

void BM_TouchdownModalStep(benchmark::State& state) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  TouchdownForces forces = MakeForces(model);
  ModalOptions options;
  options.count = static_cast<int>(state.range(0));
  const ModalModel modal = MakeModalModel(model, SolveModal(model, options), DampingModel{});
  NonlinearModalIntegrator integrator(model, modal, TipForce(model), forces,
                                      kStep / model.units().time);
  const int n = model.FreeDofCount();
  Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
  if (integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), s) != Status::kOk) {
    state.SkipWithError("initialisation failed");
    return;
  }
  RunTouchdown(state, integrator, [&](double amplitude) {
    s[0] = amplitude;
    return integrator.Step(s);
  });
  state.counters["stuck_events"] = forces.get<0>().events().stuck;
}
BENCHMARK(BM_TouchdownModalStep)->ArgName("modes")->Arg(4)->Arg(8)->Arg(16);

void BM_TouchdownNewmarkStep(benchmark::State& state) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 1));
  TouchdownForces forces = MakeForces(model);
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, forces,
                                        GeneralizedAlphaParameters::FromSpectralRadius(0.6),
                                        kStep / model.units().time);
  const Eigen::VectorXd pattern = TipForce(model);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.FreeDofCount());
  if (integrator.Initialize(f, f, f) != Status::kOk) {
    state.SkipWithError("initialisation failed");
    return;
  }
  RunTouchdown(state, integrator, [&](double amplitude) {
    f = amplitude * pattern;
    return integrator.Step(f);
  });
  state.counters["stuck_events"] = forces.get<0>().events().stuck;
}
BENCHMARK(BM_TouchdownNewmarkStep);

}  // namespace
}  // namespace cosmems
