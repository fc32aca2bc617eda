// What each effect adds to a time step, and proof that an absent one adds nothing. The planar
// 20-element reference cantilever of the embedded scene `cantilever` (its one-member netlist),
// stepped at 1 us (f1 = 68.8 kHz) by generalised-alpha with rho_inf = 0.6 (what contact needs),
// built the way `cosmems run` builds a transient: the scene's [effects] decide which forces exist
// (FrameSceneForces, the electrodes at the scene's voltage among them), and with none the linear
// fast path runs.
//   BM_BareLinearStep      the linear integrator made directly, with no scene layer at all
//   BM_EffectStep/none     the same beam through the scene layer with no effect declared
//   BM_EffectStep/contact_idle contact declared, the beam ringing under the scene's small tip
//                          force far above the substrate (idle steps)
//   BM_EffectStep/<effect> one effect declared; the tip force presses the beam onto the
//                          substrate for contact and stiction (2x the force that closes the gap)
// The per-step cost is the mean over many steps after 2000 steps of settling.
#include <string>
#include <utility>
#include <vector>

#include "cosmems/scene/frame_conversion.hpp"
#include "cosmems/scene/frame_scene_forces.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

constexpr double kTimeStep = 1e-6;
constexpr int kSettle = 2000;

template <typename Integrator>
void March(benchmark::State& state, Integrator& integrator, const Eigen::VectorXd& f) {
  const int n = static_cast<int>(f.size());
  if (integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f) != Status::kOk) {
    state.SkipWithError("initialisation failed");
    return;
  }
  for (int i = 0; i < kSettle; ++i) {
    if (integrator.Step(f) != Status::kOk) state.SkipWithError("settling failed");
  }
  for (auto _ : state) {
    if (integrator.Step(f) != Status::kOk) state.SkipWithError("step failed");
    benchmark::DoNotOptimize(integrator.displacement().data());
  }
}

void BM_BareLinearStep(benchmark::State& state) {
  const FrameModel model(bench::ReferenceChain(StructureKind::kCantilever, 20, 1, true));
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {},
                                     GeneralizedAlphaParameters::FromSpectralRadius(0.6),
                                     kTimeStep / model.units().time);
  March(state, integrator, AssembleFrameLoads(model, bench::ChainTipForce(1e-7)));
}
BENCHMARK(BM_BareLinearStep)->Unit(benchmark::kNanosecond);

// The planar cantilever scene with the overrides `sets`.
Scene PlanarScene(std::vector<std::string> sets) {
  sets.push_back("model.dimension=2");
  std::vector<SceneOverride> overrides;
  for (const std::string& set : sets) overrides.push_back(SceneOverride::Parse(set));
  return LoadScene("cantilever", overrides);
}

// Marches the model under the load f with `forces` (nullptr: the linear fast path).
void MarchTheEffects(benchmark::State& state, const FrameModel& model, NonlinearForce* forces,
                     const Eigen::VectorXd& f) {
  const auto parameters = GeneralizedAlphaParameters::FromSpectralRadius(0.6);
  const double dt = kTimeStep / model.units().time;
  if (forces == nullptr) {
    LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, parameters, dt);
    March(state, integrator, f);
  } else {
    NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, *forces, parameters,
                                          dt);
    March(state, integrator, f);
    state.counters["newton_iterations"] = integrator.last_stats().iterations;
    state.counters["residuals"] = integrator.last_stats().evaluations;
  }
  state.counters["dofs"] = model.FreeDofCount();
}

void BM_EffectStep(benchmark::State& state, std::vector<std::string> sets) {
  const Scene scene = PlanarScene(std::move(sets));
  const StructureDescription structure = MakeStructureDescription(scene);
  const FrameModel model(structure, MakeFrameCouplings(scene));
  FrameSceneForces scene_forces(model, scene);
  ForceSum& forces = scene_forces.all();
  if (scene_forces.electrodes()) forces.Add(*scene_forces.electrodes());
  MarchTheEffects(state, model, forces.Empty() ? nullptr : &forces,
                  AssembleFrameLoads(model, MakeFrameLoadCase(scene, structure)));
}

const std::string kPressed = "loads.tip_force=[0.0, -3.4e-6, 0.0]";
BENCHMARK_CAPTURE(BM_EffectStep, none, {});
BENCHMARK_CAPTURE(BM_EffectStep, contact, {"effects.contact.enabled=true", kPressed});
// Declared, but the beam rings far above the substrate: the idle steps of the linear structure.
BENCHMARK_CAPTURE(BM_EffectStep, contact_idle, {"effects.contact.enabled=true"});
BENCHMARK_CAPTURE(BM_EffectStep, stiction, {"effects.stiction.adhesion_energy=0.02", kPressed});
BENCHMARK_CAPTURE(BM_EffectStep, electrostatic_10V, {"effects.electrostatic.voltage=10.0"});
BENCHMARK_CAPTURE(BM_EffectStep, casimir, {"effects.casimir.enabled=true"});
BENCHMARK_CAPTURE(BM_EffectStep, van_der_waals, {"effects.van_der_waals.hamaker=1e-19"});
BENCHMARK_CAPTURE(BM_EffectStep, squeeze_film, {"effects.squeeze_film.viscosity=1.81e-5"});
BENCHMARK_CAPTURE(BM_EffectStep, contact_stiction_casimir,
                  {"effects.stiction.adhesion_energy=0.02", "effects.casimir.enabled=true",
                   kPressed});

}  // namespace
}  // namespace cosmems
