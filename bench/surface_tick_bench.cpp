// One haptic tick of the paper's scene: the 20-element reference cantilever over a substrate 2 um
// below, with contact, stiction (Gamma = 0.02 J/m^2) and the Casimir force, composed at compile
// time (ForceTuple), advanced by 1 ms of simulated time per tick. The beam's first mode is at
// 68.8 kHz, so a tick is 69 of its periods: generalised-alpha with rho_inf = 0 takes it in
// `substeps` implicit steps that annihilate the unresolved vibrations, each Newton to the haptic
// tolerance (HapticPhysicsOptions::residual_tolerance). As the tip nears the
// substrate the Casimir pressure snaps it on within a step, and with little mass in the step's
// matrix the tangent turns indefinite: Newton then solves with the mass term raised until the
// matrix is definite (NonlinearNewmarkIntegrator), and cuts the step only if that fails, so one
// or two steps a tick do. The hand presses the tip down onto the substrate, holds, and pulls
// it off, over and over (500 ticks a cycle); every tick is timed, and the counters give the
// median, the 99th percentile and the largest, on the wall clock and on the thread's CPU clock
// (cpu_*): the difference is time the thread spent preempted, which the machine decides.
#include <time.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "cosmems/analysis/step_timing.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/beam/force_tuple.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/structure/folded_flexure.hpp"
#include "cosmems/structure/straight_beam.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "cosmems/surface/gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "flop_rate.hpp"
#include "reference_beam.hpp"

namespace cosmems {
namespace {

constexpr double kGap = 2e-6;
constexpr int kCycle = 500;

// The hand's tip force at tick i [N]: down to 3 times the force that closes the gap, hold, then
// up to 5 times that force the other way, which peels the tip off (it lets go near 3, where its
// energy release rate reaches the work of adhesion).
double HandForce(long tick) {
  const double closing = 0.845 * kGap;  // tip stiffness 3EI/L^3 times the gap
  const double s = static_cast<double>(tick % kCycle) / kCycle;
  if (s < 0.3) return -3.0 * closing * s / 0.3;
  if (s < 0.5) return -3.0 * closing;
  if (s < 0.8) return -3.0 * closing + 8.0 * closing * (s - 0.5) / 0.3;
  return 0.0;
}

// The paper's contact and stiction: asperities 20 nm high (see SubstrateContact), 0.02 J/m^2.
ContactOptions PaperContact() {
  ContactOptions contact;
  contact.gap = kGap;
  contact.separation = 2e-8;
  contact.stiction = true;
  contact.adhesion_energy = 0.02;
  return contact;
}

// Contact, stiction and the Casimir pressure of the paper's scene on the beam, composed at
// compile time.
using Surface = ForceTuple<SubstrateContact<2>, GapForce<2, CasimirPressure>>;
Surface MakeSurface(const BeamModel<2>& model) {
  const ContactOptions contact = PaperContact();
  return Surface(
      SubstrateContact<2>(model, contact),
      GapForce<2, CasimirPressure>(model, CasimirPressure{},
                                   GapSpan{kGap, 0.0, 200e-6}.WithSeparation(contact.separation)));
}

// The same forces on the cantilever's one-member netlist, as a scene builds them.
struct ChainSurface {
  explicit ChainSurface(const FrameModel& model)
      : contact(model, PaperContact()), casimir(model, CasimirPressure{}, Under()) {
    all.Add(contact);
    all.Add(casimir);
  }
  static FrameGapOptions Under() {
    FrameGapOptions under{kGap};
    under.separation = PaperContact().separation;
    return under;
  }
  FrameSubstrateContact contact;
  FrameGapForce<CasimirPressure> casimir;
  ForceSum all;
};

// The planar reference cantilever's netlist, Hermite elements.
FrameModel PlanarChain() {
  return FrameModel(bench::ReferenceChain(StructureKind::kCantilever, 20, 0, true));
}

// Times every call of `tick` (false: it failed) and sets the median, p99 and largest, on the
// wall clock and on the thread's CPU clock; returns the wall-clock times [us].
template <typename Tick>
std::vector<double> TimeTicks(benchmark::State& state, Tick&& tick) {
  std::vector<double> times, cpu_times;
  times.reserve(1 << 20);
  cpu_times.reserve(1 << 20);
  auto cpu_now_us = [] {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e6 + static_cast<double>(t.tv_nsec) * 1e-3;
  };
  for (auto _ : state) {
    const double cpu_start = cpu_now_us();
    const auto start = std::chrono::steady_clock::now();
    const bool ok = tick();
    times.push_back(
        std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
            .count());
    cpu_times.push_back(cpu_now_us() - cpu_start);
    if (!ok) {
      state.SkipWithError("a step failed");
      break;
    }
  }
  if (times.empty()) return times;
  const StepTiming timing = StepTiming::From(times);
  const StepTiming cpu = StepTiming::From(std::move(cpu_times));
  state.counters["median_us"] = timing.median_us;
  state.counters["p99_us"] = timing.p99_us;
  state.counters["max_us"] = timing.max_us;
  state.counters["cpu_median_us"] = cpu.median_us;
  state.counters["cpu_p99_us"] = cpu.p99_us;
  state.counters["cpu_max_us"] = cpu.max_us;
  return times;
}

// The hand's force on the tip dof, `substeps` steps of the haptic integrator a tick.
template <class Model, class Contact>
void PushTheTip(benchmark::State& state, const Model& model, NonlinearForce& forces, int tip,
                const Contact& contact) {
  const int substeps = static_cast<int>(state.range(0));
  const double dt = 1e-3 / substeps / model.units().time;
  NewtonOptions newton;  // the haptic step's
  newton.residual_tolerance = HapticPhysicsOptions{}.residual_tolerance;
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, forces,
                                        GeneralizedAlphaParameters::FromSpectralRadius(0.0), dt,
                                        newton);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.FreeDofCount());
  if (integrator.Initialize(f, f, f) != Status::kOk) state.SkipWithError("initialisation failed");
  long tick = 0;
  TimeTicks(state, [&] {
    f[tip] = HandForce(++tick) / model.units().force;
    for (int i = 0; i < substeps; ++i) {
      if (integrator.Step(f) != Status::kOk) return false;
    }
    return true;
  });
  state.counters["stuck_events"] = static_cast<double>(contact.events().stuck);
  state.counters["releases"] = static_cast<double>(contact.events().releases);
}

void BM_SurfaceTick(benchmark::State& state) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, 20, 0));
  Surface forces = MakeSurface(model);
  PushTheTip(state, model, forces, model.dofs().Reduced(20, NodalDof::kUy), forces.get<0>());
}

// The same on the netlist every front end builds, its forces summed at run time as a scene's.
void BM_SurfaceTickChain(benchmark::State& state) {
  const FrameModel model = PlanarChain();
  ChainSurface forces(model);
  PushTheTip(state, model, forces.all, model.CarrierDof(model.mesh().nodes[1].carrier, 1),
             forces.contact);
}

// 1, 2, 10 and 20 steps a tick, whole cycles, so that pressing, holding and peeling all count.
void SubstepRuns(benchmark::internal::Benchmark* b) {
  b->Arg(1)->Arg(2)->Arg(10)->Arg(20)->ArgName("substeps")->Iterations(10 * kCycle);
  b->Unit(benchmark::kMicrosecond);
}
BENCHMARK(BM_SurfaceTick)->Apply(SubstepRuns);
BENCHMARK(BM_SurfaceTickChain)->Apply(SubstepRuns);

// The touched cantilever's physics: the full model's path (modes = 0) or the modal one (the
// benchmark's argument, Q = 100).
HapticPhysicsOptions TipPressPhysics(const benchmark::State& state) {
  HapticPhysicsOptions physics;
  physics.modes = static_cast<int>(state.range(0));
  physics.path = physics.modes > 0 ? TimePath::kModal : TimePath::kNewmarkFamily;
  physics.damping = DampingModel::QualityFactor(100);
  return physics;
}

// The full model and 4 and 8 modes, four cycles each.
void TipPressRuns(benchmark::internal::Benchmark* b) {
  b->Arg(0)
      ->Arg(4)
      ->Arg(8)
      ->ArgName("modes")
      ->Iterations(4 * kCycle)
      ->Unit(benchmark::kMicrosecond);
}

// Times the probe pressing the tip 4 um down, past the substrate, and lifting it 3 um clear,
// kCycle ticks a cycle.
void PressTheTip(benchmark::State& state, HapticPhysics& touched) {
  long tick = 0;
  TimeTicks(state, [&] {
    const double s = static_cast<double>(tick % kCycle) / kCycle;
    const double depth = s < 0.5 ? 4e-6 * s / 0.5 : 4e-6 - 7e-6 * (s - 0.5) / 0.5;
    ++tick;
    return touched.Advance(Eigen::Vector3d(200e-6, 1e-6 - depth + 2e-6, 0.0), 0.0) == Status::kOk;
  });
}

// The tick the hand feels on the reference cantilever as the command line touches it (its
// one-member netlist, StraightBeam, planar: the beam's unknowns and band; HapticStructure): the
// probe (coupling 5 N/m, radius 2 um) presses the tip 4 um down, past the substrate, and lifts it
// 3 um clear, over and over (kCycle ticks a cycle), with the paper's contact, stiction and
// Casimir force, on the full model's path or the modal one (`modes` modes, Q = 100), at the
// haptic default of steps a tick (HapticPhysicsOptions::substeps).
void BM_TouchedChainTick(benchmark::State& state) {
  const FrameModel model = PlanarChain();
  ChainSurface forces(model);
  const HapticPhysicsOptions physics = TipPressPhysics(state);
  HapticStructure chain(model, ProbeOptions{2e-6, 5.0}, &forces.all, &forces.contact, physics);
  PressTheTip(state, chain);
  state.counters["stuck_events"] = static_cast<double>(forces.contact.events().stuck);
}
BENCHMARK(BM_TouchedChainTick)->Apply(TipPressRuns);

// The tick the hand feels on a device (HapticStructure): the folded-flexure resonator with
// `elements` per beam (8 beams: 80 elements at 10, 1000 at 125) over a substrate 2 um below,
// with the Casimir force (`casimir` = 1) or the probe alone (0), and with the substrate's contact
// (`contact` = 1: the coupling 50 N/m presses the shuttle onto the substrate, 4 um deep; 2: with
// stiction too, Gamma = 1e-6 J/m^2, which holds the shuttle down from the first press on: one
// stuck event and no release a row) or without it (the coupling 5 N/m, 2 um deep, the
// shuttle never reaching the substrate); the probe (radius 2 um) presses the shuttle's upper face
// 3 um off its centre and lifts 1 um clear, over and over, on the full model's path
// (generalised-alpha, 1 step a tick) or the modal one (`modes` modes, Q = 100). The Casimir
// force's quadrature halves a face until its gap varies by at most `gap_ratio_pct` / 100 over
// it (FrameGapOptions::gap_ratio; 125 the default, 10000 no halving): what its accuracy near the
// substrate costs in the tick.
struct TouchedDevice {
  int elements = 10, modes = 0, casimir = 1, contact = 2, gap_ratio_pct = 125;
  bool held = false;  ///< the Casimir pressure held at the contact's separation, as scenes build it
  int substeps = HapticPhysicsOptions{}.substeps;
  double residual_tolerance = HapticPhysicsOptions{}.residual_tolerance;
};

// The resonator of `c` under its probe, ready for its first tick.
class PressedDevice {
 public:
  explicit PressedDevice(const TouchedDevice& c)
      : model_(Design(c)),
        substrate_(Substrate(c)),
        casimir_(model_, CasimirPressure{}, Under(c, substrate_)),
        deepest_(c.contact != 0 ? 4e-6 : 2e-6) {
    if (c.casimir != 0) forces_.Add(casimir_);
    if (c.contact != 0) forces_.Add(contact_.emplace(model_, substrate_));
    HapticPhysicsOptions physics;
    physics.modes = c.modes;
    physics.substeps = c.substeps;
    physics.residual_tolerance = c.residual_tolerance;
    physics.path = physics.modes > 0 ? TimePath::kModal : TimePath::kNewmarkFamily;
    physics.damping = DampingModel::QualityFactor(100);
    structure_.emplace(model_, ProbeOptions{2e-6, contact_ ? 50.0 : 5.0},
                       forces_.Empty() ? nullptr : &forces_, contact_ ? &*contact_ : nullptr,
                       physics);
  }

  // The next tick of the press; false where it failed.
  bool Tick() {
    const double s = static_cast<double>(tick_ % kCycle) / kCycle;
    const double depth =
        s < 0.5 ? deepest_ * s / 0.5 : deepest_ - (deepest_ + 1e-6) * (s - 0.5) / 0.5;
    ++tick_;
    const Eigen::Vector3d probe(3e-6, 1e-6 + 2e-6 - depth, 5e-6);
    return structure_->Advance(probe, 0.0) == Status::kOk;
  }

  void SetCounters(benchmark::State& state) const {
    state.counters["dofs"] = model_.FreeDofCount();
    state.counters["band"] = model_.Stiffness().bandwidth();
    if (!contact_) return;
    state.counters["contacts"] = static_cast<double>(contact_->events().contacts);
    if (!substrate_.stiction) return;
    state.counters["stuck_events"] = static_cast<double>(contact_->events().stuck);
    state.counters["releases"] = static_cast<double>(contact_->events().releases);
  }

 private:
  static StructureDescription Design(const TouchedDevice& c) {
    FoldedFlexureDesign design;
    design.elements = c.elements;
    return FoldedFlexure(design);
  }
  static ContactOptions Substrate(const TouchedDevice& c) {
    ContactOptions substrate;
    substrate.gap = kGap;
    substrate.separation = 1e-2 * kGap;  // the scenes' default beside a surface pressure
    substrate.stiction = c.contact == 2;
    substrate.adhesion_energy = 1e-6;
    return substrate;
  }
  static FrameGapOptions Under(const TouchedDevice& c, const ContactOptions& substrate) {
    FrameGapOptions under{kGap};
    under.gap_ratio = c.gap_ratio_pct / 100.0;
    if (c.held) under.separation = substrate.separation;
    return under;
  }

  FrameModel model_;
  ContactOptions substrate_;
  FrameGapForce<CasimirPressure> casimir_;
  std::optional<FrameSubstrateContact> contact_;
  ForceSum forces_;
  std::optional<HapticStructure> structure_;
  double deepest_;
  long tick_ = 0;
};

void TouchDevice(benchmark::State& state, const TouchedDevice& c) {
  PressedDevice device(c);
  TimeTicks(state, [&] { return device.Tick(); });
  device.SetCounters(state);
}

void BM_TouchedDeviceTick(benchmark::State& state) {
  TouchedDevice c;
  c.elements = static_cast<int>(state.range(0));
  c.modes = static_cast<int>(state.range(1));
  c.casimir = static_cast<int>(state.range(2));
  c.contact = static_cast<int>(state.range(3));
  c.gap_ratio_pct = static_cast<int>(state.range(4));
  TouchDevice(state, c);
}
BENCHMARK(BM_TouchedDeviceTick)
    ->Args({10, 0, 0, 0, 125})
    ->Args({10, 0, 1, 0, 125})
    ->Args({10, 0, 1, 1, 125})
    ->Args({10, 0, 1, 1, 150})
    ->Args({10, 0, 1, 1, 200})
    ->Args({10, 0, 1, 1, 10000})
    ->Args({10, 0, 1, 2, 125})
    ->Args({10, 8, 1, 0, 125})
    ->Args({10, 8, 1, 2, 125})
    ->Args({125, 0, 0, 0, 125})
    ->Args({125, 0, 1, 0, 125})
    ->Args({125, 0, 1, 1, 125})
    ->Args({125, 0, 1, 2, 125})
    ->Args({125, 8, 1, 0, 125})
    ->Args({125, 8, 1, 2, 125})
    ->ArgNames({"elements", "modes", "casimir", "contact", "gap_ratio_pct"})
    ->Iterations(2 * kCycle)
    ->Unit(benchmark::kMicrosecond);

// The computation alone of the pressed resonator's tick (BM_TouchedDeviceTick's row
// elements:10/modes:0/casimir:1/contact:2/gap_ratio_pct:125): its 1000 ticks replayed from the
// start five times (the benchmark's iterations), each tick's least time kept, so that the
// machine's stalls (BM_FixedWorkTick), which land on a tick in one replay and not in the others,
// drop out. The counters are the median and p99 of those least times.
void BM_TouchedDeviceTickLeast(benchmark::State& state) {
  const TouchedDevice c;  // that row's
  std::vector<double> least(2 * kCycle, std::numeric_limits<double>::infinity());
  for (auto _ : state) {
    state.PauseTiming();
    PressedDevice device(c);
    state.ResumeTiming();
    for (double& t : least) {
      const auto start = std::chrono::steady_clock::now();
      if (!device.Tick()) {
        state.SkipWithError("a step failed");
        return;
      }
      t = std::min(
          t, std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                 .count());
    }
  }
  const StepTiming timing = StepTiming::From(least);
  state.counters["least_median_us"] = timing.median_us;
  state.counters["least_p99_us"] = timing.p99_us;
}
BENCHMARK(BM_TouchedDeviceTickLeast)->Iterations(5)->Unit(benchmark::kMillisecond);

// The pressed resonator with contact, stiction and the Casimir pressure as a scene builds them
// (FrameSceneForces): the pressure held at the contact's separation from below, where the rows
// above let it grow through the contact's penetration (by 4 % at the contact's tolerance). The
// hold leaves the pressure's stiffness a jump at the contact plane, where a kept factor's
// correction throws the landing step's iterate far through it: NewtonDriver undoes it and
// factors afresh where it started (without that the iterates cycled until the step was cut).
void BM_TouchedDeviceTickHeld(benchmark::State& state) {
  TouchedDevice c;
  c.elements = static_cast<int>(state.range(0));
  c.held = true;
  TouchDevice(state, c);
}
BENCHMARK(BM_TouchedDeviceTickHeld)
    ->Arg(10)
    ->ArgName("elements")
    ->Iterations(2 * kCycle)
    ->Unit(benchmark::kMicrosecond);

// What accuracy costs in the tick: the same resonator with Casimir, contact and stiction (the
// rows above with casimir 1, contact 2) at `substeps` generalised-alpha steps a tick and Newton's
// residual tolerance 10^-`tolerance_exp` instead of the defaults, 1 and 1e-6 (that row above).
// Every tick must still converge (a failed tick ends the row with an error).
void BM_TouchedDeviceTickAccuracy(benchmark::State& state) {
  TouchedDevice c;
  c.elements = static_cast<int>(state.range(0));
  c.substeps = static_cast<int>(state.range(1));
  c.residual_tolerance = std::pow(10.0, -static_cast<double>(state.range(2)));
  TouchDevice(state, c);
}
BENCHMARK(BM_TouchedDeviceTickAccuracy)
    ->Args({10, 2, 6})
    ->Args({10, 4, 6})
    ->Args({10, 2, 8})
    ->Args({10, 2, 10})
    ->ArgNames({"elements", "substeps", "tolerance_exp"})
    ->Iterations(2 * kCycle)
    ->Unit(benchmark::kMicrosecond);

// The machine's own share of a tick's p99: a tick of fixed arithmetic (eight independent
// multiply-add chains, the yardstick of flop_rate.hpp) sized to `work_us` at the machine's rate,
// timed as the ticks above. Its work never changes, so whatever spreads its p99 and maximum
// beyond its median is the machine: interrupts, the other core's load, a virtual machine's host.
void BM_FixedWorkTick(benchmark::State& state) {
  const double work_us = static_cast<double>(state.range(0));
  const long rounds = std::lround(work_us * 1e3 / (2.0 * 8.0 * bench::NanosecondsPerFlop()));
  std::array<double, 8> chain{1.0, 1.1, 1.2, 1.3, 1.4, 1.5, 1.6, 1.7};
  double a = 0.999999, b = 1e-9;
  benchmark::DoNotOptimize(a);
  benchmark::DoNotOptimize(b);
  const std::vector<double> times = TimeTicks(state, [&] {
    bench::MultiplyAddChains(chain, a, b, rounds);
    benchmark::DoNotOptimize(chain.data());
    return true;
  });
  // The stalls: ticks longer than the median by more than kStallUs, counted per millisecond of
  // ticking (a periodic interrupt shows as its rate), and their median excess.
  constexpr double kStallUs = 20.0;
  const double median = state.counters["median_us"];
  std::vector<double> excess;
  double elapsed_us = 0.0;
  for (const double t : times) {
    elapsed_us += t;
    if (t > median + kStallUs) excess.push_back(t - median);
  }
  state.counters["stalls_per_ms"] = 1e3 * static_cast<double>(excess.size()) / elapsed_us;
  state.counters["stall_median_us"] = StepTiming::From(excess).median_us;
}
BENCHMARK(BM_FixedWorkTick)
    ->Arg(20)
    ->Arg(100)
    ->ArgName("work_us")
    ->Iterations(4 * kCycle)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
