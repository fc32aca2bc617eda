// The accuracy-versus-time report: the model choices of the library (element count, series
// order, theory, full or modal dynamics, integrator, time step) priced on reference problems
// whose answers are known without the library's models.
//
// Each benchmark is one setting of one problem, named "problem/key:value/...". Its timed loop is
// the call a user makes (a modal solve, a static or pull-in solve from rest, one time step) and
// its counter rel_error is the relative error of that call's answer against the reference; a
// time step also reports steps_per_tick, the steps that cover one 1 ms haptic tick. main()
// writes accuracy_cost.csv and accuracy_cost.md (medians over --benchmark_repetitions, the
// Pareto front of each problem) into --report_dir (default: the current directory);
// bench/accuracy_cost_report.sh runs it and plots the CSV with bench/accuracy_cost.gp.
//
// The references: the roots of cos x cosh x = -1 (tests/test_beams.hpp), the elastica by
// shooting (tests/rod/elastica.hpp), the tie-beam solution of a stretched bridge
// (tests/beam/stretched_bridge.hpp), pull-in by shooting the beam equation
// (tests/surface/beam_shooting.hpp) and the released cantilever's modal series
// (cantilever_release.hpp).
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accuracy_cost_reporter.hpp"
#include "beam/stretched_bridge.hpp"
#include "cantilever_release.hpp"
#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/rod/rod_load_case.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/modal_model.hpp"
#include "reference_beam.hpp"
#include "rod/elastica.hpp"
#include "surface/beam_shooting.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

constexpr double kLength = test::kReferenceLength;  // m, also bench::ReferenceBeam's
constexpr double kGap = 2e-6;                       // m, under the beam in the pull-in problems
constexpr double kTick = 1e-3;                      // s, one tick of the 1 kHz haptic loop
// The physics' share of a tick: a tenth of the period, the target the haptic tick benchmarks
// hold the physics to, leaving the rest to contact, the probe and the servo side.
constexpr double kTickBudgetUs = 100.0;

double ReferenceEi() {
  return test::Silicon().young_modulus * test::ReferenceSection().SecondMomentZ();
}
double ReferenceEa() { return test::Silicon().young_modulus * test::ReferenceSection().Area(); }
double ReferenceRhoA() { return test::Silicon().density * test::ReferenceSection().Area(); }

std::string Number(double value) {
  std::array<char, 32> buffer{};
  std::snprintf(buffer.data(), buffer.size(), "%.3g", value);
  return buffer.data();
}

/// Registers `measure` as the benchmark "problem/key:value/...", labelled with its settings.
template <typename Measure>
void Register(const std::string& problem, const bench::Settings& settings, benchmark::TimeUnit unit,
              Measure measure) {
  std::string name = problem;
  for (const auto& [key, value] : settings) name.append("/").append(key).append(":").append(value);
  const std::string label = bench::SettingsLabel(settings);
  benchmark::RegisterBenchmark(name.c_str(), [measure, label](benchmark::State& state) {
    measure(state);
    state.SetLabel(label);
  })->Unit(unit);
}

// --- Frequencies -------------------------------------------------------------------------------

// The first four bending frequencies of the planar reference cantilever against the roots of
// cos x cosh x = -1: the largest of the four relative errors. Timed: SolveModal for 4 modes.
void MeasureFrequencies(benchmark::State& state, int elements, int order) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, elements, order));
  ModalOptions options;
  options.count = 4;
  ModalResult result;
  for (auto _ : state) result = SolveModal(model, options);
  if (result.status != Status::kOk || result.modes.size() < 4) {
    state.SkipWithError("modal solve failed");
    return;
  }
  double error = 0.0;
  for (int i = 0; i < 4; ++i) {
    if (result.modes[i].kind != ModeKind::kBendingY) {
      state.SkipWithError("a mode other than bending among the first four");
      return;
    }
    const double root = test::FrequencyRoot(i + 1, -1.0);
    const double exact = test::BendingFrequency(root, kLength, ReferenceEi(), ReferenceRhoA());
    error = std::max(error, std::abs(result.modes[i].frequency_hz / exact - 1.0));
  }
  state.counters["rel_error"] = error;
}

void RegisterFrequencies() {
  for (int order : {0, 1, 2, 3}) {
    for (int elements : {4, 8, 16, 32}) {
      Register("frequencies",
               {{"order", std::to_string(order)}, {"elements", std::to_string(elements)}},
               benchmark::kMicrosecond,
               [=](benchmark::State& state) { MeasureFrequencies(state, elements, order); });
    }
  }
}

// --- A tip force on the cantilever ------------------------------------------------------------

// A dead tip force P = alpha EI / L^2 toward the substrate, against the elastica of the same
// alpha. `position`: the error is that of the tip's whole displacement (the shortening too),
// relative to its length; otherwise that of the deflection along the load. Linear theory has no
// shortening and its static solution is exact at the nodes, so its error is the theory's alone
// and the same for every mesh. The elastica is inextensible and unshearable: the Kirchhoff rod
// converges to it, the physical (Simo-Reissner) rod only to within its own extension and shear
// (about 8e-5 at PL^2/EI = 5), where its error stops falling.
struct TipLoadProblem {
  const char* name;
  double alpha;
  bool position;
};

const test::ElasticaTip& ElasticaOf(double alpha) {
  static std::map<double, test::ElasticaTip> cache;
  auto it = cache.find(alpha);
  if (it == cache.end()) it = cache.emplace(alpha, test::Elastica(alpha)).first;
  return it->second;
}

double TipError(const TipLoadProblem& problem, double shortening, double deflection) {
  const test::ElasticaTip& exact = ElasticaOf(problem.alpha);
  if (!problem.position) return std::abs(deflection / exact.deflection - 1.0);
  return std::hypot(shortening - exact.shortening, deflection - exact.deflection) /
         std::hypot(exact.shortening, exact.deflection);
}

double TipForce(const TipLoadProblem& problem) {
  return problem.alpha * ReferenceEi() / (kLength * kLength);
}

void MeasureLinearTip(benchmark::State& state, const TipLoadProblem& problem, int elements) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, elements, 1));
  LoadCase loads;
  loads.points.push_back(
      {kLength, Eigen::Vector3d(0.0, -TipForce(problem), 0.0), Eigen::Vector3d::Zero()});
  StaticSolution solution;
  for (auto _ : state) solution = SolveStatic(model, loads);
  if (solution.status != Status::kOk) {
    state.SkipWithError("static solve failed");
    return;
  }
  const auto tip = BeamField<2>(model, solution.displacement).At(kLength);
  state.counters["rel_error"] = TipError(problem, -tip[0] / kLength, -tip[1] / kLength);
}

// Times a static rod solve from rest; false (the benchmark marked failed) when it does not
// converge.
bool TimeRodSolve(benchmark::State& state, CosseratStaticSolver& solver, const RodLoads& loads) {
  Status status = Status::kOk;
  for (auto _ : state) {
    solver.Reset();
    status = solver.Solve(loads);
  }
  if (status != Status::kOk) state.SkipWithError("rod solve failed");
  return status == Status::kOk;
}

void MeasureRodTip(benchmark::State& state, const TipLoadProblem& problem, int elements,
                   RodTheory theory) {
  CosseratOptions options;
  options.theory = theory;
  const CosseratRod rod(bench::ReferenceBeam(StructureKind::kCantilever, elements, 0), options);
  CosseratStaticSolver solver(rod);
  const RodLoads loads =
      RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d(0.0, -TipForce(problem), 0.0),
                      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  if (!TimeRodSolve(state, solver, loads)) return;
  const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / kLength;
  state.counters["rel_error"] = TipError(problem, -tip.x(), -tip.y());
}

void RegisterTipLoad(const TipLoadProblem& problem, const std::vector<int>& rod_elements) {
  for (int elements : {2, 20}) {
    Register(problem.name, {{"theory", "linear"}, {"elements", std::to_string(elements)}},
             benchmark::kMicrosecond,
             [=](benchmark::State& state) { MeasureLinearTip(state, problem, elements); });
  }
  for (const RodTheory theory : {RodTheory::kKirchhoff, RodTheory::kSimoReissner}) {
    const char* name = theory == RodTheory::kKirchhoff ? "cosserat-kirchhoff" : "cosserat";
    for (int elements : rod_elements) {
      Register(problem.name, {{"theory", name}, {"elements", std::to_string(elements)}},
               benchmark::kMicrosecond,
               [=](benchmark::State& state) { MeasureRodTip(state, problem, elements, theory); });
    }
  }
}

// --- A stretched bridge -----------------------------------------------------------------------

// The reference bridge under 100 N/m, pressed about five thicknesses deep, against the tie-beam
// solution of mid-plane stretching: the relative error of the midspan deflection. That reference
// is itself a small-slope theory (slopes up to 0.07 here), so the rod, which needs no such
// assumption, differs from it by about w'^2 (0.3 %) besides its discretisation error.
constexpr double kBridgeLoad = -100.0;  // N/m

double BridgeError(double midspan) {
  static const double exact =
      test::SolveStretchedBridge(kLength, ReferenceEi(), ReferenceEa(), kBridgeLoad, 0.0).midspan;
  return std::abs(midspan / exact - 1.0);
}

LoadCase BridgeLoads() {
  LoadCase loads;
  loads.distributed = Eigen::Vector3d(0.0, kBridgeLoad, 0.0);
  return loads;
}

void MeasureBridgeBeam(benchmark::State& state, int elements, bool stretching) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kBridge, elements, 1));
  const LoadCase loads = BridgeLoads();
  Eigen::VectorXd displacement;
  Status status = Status::kOk;
  if (stretching) {
    StretchingForce<2> force(model);
    for (auto _ : state) {
      const NonlinearStaticSolution solution = SolveNonlinearStatic(model, force, loads);
      status = solution.status;
      displacement = solution.displacement;
    }
  } else {
    for (auto _ : state) {
      const StaticSolution solution = SolveStatic(model, loads);
      status = solution.status;
      displacement = solution.displacement;
    }
  }
  if (status != Status::kOk) {
    state.SkipWithError("static solve failed");
    return;
  }
  state.counters["rel_error"] = BridgeError(BeamField<2>(model, displacement).At(kLength / 2)[1]);
}

void MeasureBridgeRod(benchmark::State& state, int elements) {
  const CosseratRod rod(bench::ReferenceBeam(StructureKind::kBridge, elements, 0));
  CosseratStaticSolver solver(rod);
  if (!TimeRodSolve(state, solver, RodLoadsFor(rod, BridgeLoads()))) return;
  state.counters["rel_error"] = BridgeError(rod.DisplacementAt(solver.state(), kLength / 2).y());
}

void RegisterBridge() {
  for (int elements : {20, 40}) {
    Register("bridge", {{"theory", "linear"}, {"elements", std::to_string(elements)}},
             benchmark::kMicrosecond,
             [=](benchmark::State& state) { MeasureBridgeBeam(state, elements, false); });
  }
  for (int elements : {5, 10, 20, 40, 80}) {
    Register("bridge", {{"theory", "stretching"}, {"elements", std::to_string(elements)}},
             benchmark::kMicrosecond,
             [=](benchmark::State& state) { MeasureBridgeBeam(state, elements, true); });
  }
  for (int elements : {20, 50, 100}) {
    Register("bridge", {{"theory", "cosserat"}, {"elements", std::to_string(elements)}},
             benchmark::kMicrosecond,
             [=](benchmark::State& state) { MeasureBridgeRod(state, elements); });
  }
}

// --- Pull-in -----------------------------------------------------------------------------------

// The pull-in voltage over a 2 um gap, the electrode under the whole beam and no fringing field,
// against the shooting solution of the pull-in tests (surface/beam_shooting.hpp): the cantilever,
// and the bridge with mid-plane stretching (without it a bridge pulls in some 6 % lower, which its
// linear rows show); and the strongly stretched bridge, 100 um long over a 4 um gap (twice its
// thickness), whose tension draws the bending into boundary layers at the clamps. Timed:
// SolvePullIn from rest.
struct PullInSetting {
  bool bridge = false;
  bool stretching = false;
  int elements = 20;
  int order = 1;
  double slope_tolerance = FoldOptions{}.slope_tolerance;
  double length = kLength;
  double gap = kGap;
};

double PullInVoltage(const PullInSetting& setting) {
  static std::map<std::array<double, 3>, double> cache;
  const std::array<double, 3> key = {setting.bridge ? 1.0 : 0.0, setting.length, setting.gap};
  auto it = cache.find(key);
  if (it == cache.end()) {
    const double g = setting.gap;
    const double kappa = setting.bridge ? ReferenceEa() * g * g / (2.0 * ReferenceEi()) : 0.0;
    const double beta = test::BeamShooting(setting.bridge, 2, 0.0, kappa).Fold().second;
    const double width = test::ReferenceSection().width;
    const double voltage = std::sqrt(2.0 * beta * ReferenceEi() * g * g * g /
                                     (kVacuumPermittivity * width * std::pow(setting.length, 4)));
    it = cache.emplace(key, voltage).first;
  }
  return it->second;
}

void MeasurePullIn(benchmark::State& state, const PullInSetting& setting) {
  const StructureKind kind = setting.bridge ? StructureKind::kBridge : StructureKind::kCantilever;
  const BeamModel<2> model(MakeStructure(kind, setting.length, test::Silicon(),
                                         test::ReferenceSection(), setting.elements,
                                         setting.order));
  std::optional<StretchingForce<2>> stretching;
  if (setting.stretching) stretching.emplace(model);
  PullInOptions options;
  options.electrode = {setting.gap, 0.0, setting.length};
  options.control_x = setting.bridge ? setting.length / 2 : setting.length;
  options.fold.slope_tolerance = setting.slope_tolerance;
  PullInResult result;
  for (auto _ : state) result = SolvePullIn(model, options, stretching ? &*stretching : nullptr);
  if (result.status != Status::kOk) {
    state.SkipWithError("pull-in failed");
    return;
  }
  state.counters["rel_error"] = std::abs(result.voltage_v / PullInVoltage(setting) - 1.0);
}

void RegisterPullIn(const std::string& problem, const PullInSetting& setting) {
  bench::Settings settings;
  if (setting.bridge) settings.push_back({"theory", setting.stretching ? "stretching" : "linear"});
  settings.push_back({"order", std::to_string(setting.order)});
  settings.push_back({"elements", std::to_string(setting.elements)});
  settings.push_back({"fold_slope", Number(setting.slope_tolerance)});
  Register(problem, settings, benchmark::kMicrosecond,
           [=](benchmark::State& state) { MeasurePullIn(state, setting); });
}

void RegisterPullIns() {
  for (int elements : {5, 10, 20, 40}) {
    RegisterPullIn("pullin_cantilever", {false, false, elements, 1});
  }
  for (int elements : {10, 20}) RegisterPullIn("pullin_cantilever", {false, false, elements, 0});
  for (double slope : {1e-2, 1e-4}) {
    RegisterPullIn("pullin_cantilever", {false, false, 20, 1, slope});
  }
  for (int elements : {10, 20, 40, 80}) {
    RegisterPullIn("pullin_bridge", {true, true, elements, 1});
  }
  RegisterPullIn("pullin_bridge", {true, false, 40, 1});
  for (int elements : {10, 20, 40, 80}) {
    RegisterPullIn("pullin_bridge_stretched",
                   {true, true, elements, 1, FoldOptions{}.slope_tolerance, 100e-6, 4e-6});
  }
}

// --- The release transient --------------------------------------------------------------------

// The reference cantilever (planar) at rest under a tip force of 0.1 uN, released at t = 0 and
// vibrating freely, undamped, against CantileverRelease. The error is the largest
// |w_tip(t) - w_exact(t)| over the first millisecond (one haptic tick: 69 periods of f1, so the
// phase error a time step leaves accumulates over a tick), relative to the static tip
// deflection, at the same instants for every setting: t = 10, 20, ... 1000 us (every time step
// divides 10 us), since judging each setting at its own step times would judge the coarse steps
// at fewer instants. The instants fall 0.69 periods of f1 apart, at unrelated phases, so their
// largest error follows the envelope of the error. Timed: one step, the tip deflection read
// after it.
constexpr double kSampleInterval = 10e-6;  // s
constexpr double kReleaseForce = 1e-7;     // N

double StaticTip() { return kReleaseForce * std::pow(kLength, 3) / (3.0 * ReferenceEi()); }

LoadCase ReleaseLoads() {
  LoadCase loads;
  loads.points.push_back(
      {kLength, Eigen::Vector3d(0.0, -kReleaseForce, 0.0), Eigen::Vector3d::Zero()});
  return loads;
}

// The full model (K and M_0: the full-order integrators do not use the higher series terms)
// marched by a member of the Newmark family on the band solver.
class FullOrderRelease {
 public:
  FullOrderRelease(int elements, const GeneralizedAlphaParameters& parameters, double dt)
      : model_(bench::ReferenceBeam(StructureKind::kCantilever, elements, 0)),
        integrator_(model_.Mass(0), model_.Stiffness(), {}, parameters, dt / model_.units().time,
                    SpdSolverKind::kBand),
        zero_(Eigen::VectorXd::Zero(model_.FreeDofCount())),
        tip_(model_.dofs().Reduced(model_.NodeCount() - 1, NodalDof::kUy)) {
    const StaticSolution deflected = SolveStatic(model_, ReleaseLoads());
    status_ = deflected.status;
    if (status_ == Status::kOk) {
      status_ = integrator_.Initialize(deflected.displacement, zero_, zero_);
    }
  }

  Status status() const { return status_; }
  [[nodiscard]] Status Step() { return integrator_.Step(zero_); }
  /// uy at the tip [m].
  double Tip() const { return integrator_.displacement()[tip_] * model_.units().length; }

 private:
  BeamModel<2> model_;
  LinearNewmarkIntegrator integrator_;
  Eigen::VectorXd zero_;
  int tip_;
  Status status_ = Status::kOk;
};

// Exact propagation of k modes of the model, started as the library's transient analysis
// starts a release: q0 fitted to the static deflection d0 (ModalModel::Project).
class ModalRelease {
 public:
  ModalRelease(int elements, int order, int modes, double dt)
      : model_(bench::ReferenceBeam(StructureKind::kCantilever, elements, order)),
        pattern_(AssembleLoads(model_, ReleaseLoads())),
        modal_(Reduce(model_, modes, status_)),
        propagator_(modal_.coordinates, modal_.shapes, pattern_,
                    modal_.ResidualFlexibility(model_, pattern_), dt / model_.units().time),
        released_(Eigen::VectorXd::Zero(1)),
        tip_(model_.dofs().Reduced(model_.NodeCount() - 1, NodalDof::kUy)) {
    const StaticSolution deflected = SolveStatic(model_, ReleaseLoads());
    if (status_ == Status::kOk) status_ = deflected.status;
    propagator_.Initialize(modal_.Project(model_, deflected.displacement),
                           Eigen::VectorXd::Zero(modal_.shapes.cols()), released_);
  }

  Status status() const { return status_; }
  [[nodiscard]] Status Step() { return propagator_.Step(released_); }
  double Tip() const { return propagator_.DisplacementAt(tip_) * model_.units().length; }

 private:
  static ModalModel Reduce(const BeamModel<2>& model, int count, Status& status) {
    ModalOptions options;
    options.count = count;
    const ModalResult modes = SolveModal(model, options);
    status = modes.status;
    return MakeModalModel(model, modes, DampingModel{});
  }

  BeamModel<2> model_;
  Status status_ = Status::kOk;
  Eigen::MatrixXd pattern_;
  ModalModel modal_;
  ModalPropagator propagator_;
  Eigen::VectorXd released_;  ///< the load's amplitude after the release: none
  int tip_;
};

// Marches `run` over one tick and returns its largest tip error (see above); infinity when a
// step fails.
template <typename Run>
double ReleaseError(Run& run, double dt) {
  static const bench::CantileverRelease exact(kLength * kLength *
                                              std::sqrt(ReferenceRhoA() / ReferenceEi()));
  const long steps_per_sample = std::lround(kSampleInterval / dt);
  const long samples = std::lround(kTick / kSampleInterval);
  double worst = 0.0;
  for (long j = 1; j <= samples; ++j) {
    for (long i = 0; i < steps_per_sample; ++i) {
      if (run.Step() != Status::kOk) return std::numeric_limits<double>::infinity();
    }
    const double t = static_cast<double>(j * steps_per_sample) * dt;
    worst = std::max(worst, std::abs(run.Tip() / -StaticTip() - exact.TipRatio(t)));
  }
  return worst;
}

// The error of a setting does not change between the calls Google Benchmark makes to size the
// iteration count and to repeat, and a tick of the finest steps takes up to a second: it is
// computed on the first call and kept.
std::map<std::string, double>& ReleaseErrors() {
  static std::map<std::string, double> errors;
  return errors;
}

template <typename Run, typename... Args>
void MeasureRelease(benchmark::State& state, const std::string& key, double dt, Args... args) {
  Run run(args..., dt);
  if (run.status() != Status::kOk) {
    state.SkipWithError("set-up failed");
    return;
  }
  auto cached = ReleaseErrors().find(key);
  if (cached == ReleaseErrors().end()) {
    cached = ReleaseErrors().emplace(key, ReleaseError(run, dt)).first;
  }
  Status status = Status::kOk;
  for (auto _ : state) {
    status = run.Step();
    benchmark::DoNotOptimize(run.Tip());
  }
  if (status != Status::kOk || !std::isfinite(cached->second)) {
    state.SkipWithError("step failed");
    return;
  }
  state.counters["rel_error"] = cached->second;
  state.counters["steps_per_tick"] = kTick / dt;
}

/// The largest step at or below 0.9 of the central-difference stability limit 2 / w_max of the
/// full model that divides kSampleInterval [s].
double CentralDifferenceStep(int elements) {
  const BeamModel<2> model(bench::ReferenceBeam(StructureKind::kCantilever, elements, 0));
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(
      model.Stiffness().ToDense(), model.Mass(0).ToDense(), Eigen::EigenvaluesOnly);
  const double limit = 2.0 / std::sqrt(eigen.eigenvalues().maxCoeff()) * model.units().time;
  return kSampleInterval / std::ceil(kSampleInterval / (0.9 * limit));
}

// The release's settings: the scheme (a full-order integrator, or modal propagation with the
// modes of a series order) first, as it names the plots' series.
void RegisterFullOrderRelease(const std::string& integrator, int elements,
                              const GeneralizedAlphaParameters& parameters, double dt) {
  const bench::Settings settings = {
      {"scheme", integrator}, {"elements", std::to_string(elements)}, {"dt_us", Number(dt * 1e6)}};
  const std::string key = bench::SettingsLabel(settings);
  Register("release", settings, benchmark::kNanosecond, [=](benchmark::State& state) {
    MeasureRelease<FullOrderRelease>(state, key, dt, elements, parameters);
  });
}

void RegisterModalRelease(int order, int modes, double dt) {
  const bench::Settings settings = {{"scheme", "modal-order-" + std::to_string(order)},
                                    {"elements", "20"},
                                    {"modes", std::to_string(modes)},
                                    {"dt_us", Number(dt * 1e6)}};
  const std::string key = bench::SettingsLabel(settings);
  Register("release", settings, benchmark::kNanosecond, [=](benchmark::State& state) {
    MeasureRelease<ModalRelease>(state, key, dt, 20, order, modes);
  });
}

void RegisterRelease() {
  for (int modes : {1, 2, 4, 8, 12}) {
    for (double dt_us : {1.0, 10.0}) RegisterModalRelease(1, modes, dt_us * 1e-6);
  }
  // Series order 0: the modes of the plain cubic elements.
  for (int modes : {4, 8, 12}) RegisterModalRelease(0, modes, 10e-6);
  const std::vector<std::pair<std::string, GeneralizedAlphaParameters>> implicit = {
      {"average-acceleration", GeneralizedAlphaParameters::Newmark(0.25, 0.5)},
      {"hht-0.05", GeneralizedAlphaParameters::Hht(0.05)},
      {"generalized-alpha-0.8", GeneralizedAlphaParameters::FromSpectralRadius(0.8)}};
  for (const auto& [name, parameters] : implicit) {
    for (double dt_us : {1.0, 0.5, 0.2, 0.1, 0.05}) {
      RegisterFullOrderRelease(name, 20, parameters, dt_us * 1e-6);
    }
  }
  for (int elements : {5, 20}) {
    RegisterFullOrderRelease("central-difference", elements,
                             GeneralizedAlphaParameters::CentralDifference(),
                             CentralDifferenceStep(elements));
  }
}

// --- The report ---------------------------------------------------------------------------------

const TipLoadProblem kTipSmall = {"tip_small", 0.03, false};
const TipLoadProblem kTipModerate = {"tip_moderate", 0.3, false};
const TipLoadProblem kElastica = {"elastica", 5.0, true};

std::vector<bench::ProblemInfo> Problems() {
  return {
      {"frequencies", "modes 1-4 of the reference cantilever (planar)",
       "largest relative error of the four frequencies against the roots of cos x cosh x = -1",
       "one modal solve for 4 modes, needed again whenever the beam is edited"},
      {kTipSmall.name,
       "tip force PL^2/EI = 0.03 on the reference cantilever: tip 1 % of L down, the 2 um gap",
       "tip deflection along the load against the elastica", "one static solve from rest"},
      {kTipModerate.name, "tip force PL^2/EI = 0.3: tip 10 % of L down",
       "tip deflection along the load against the elastica", "one static solve from rest"},
      {kElastica.name, "tip force PL^2/EI = 5: tip 71 % of L down, turned 70 degrees",
       "tip displacement (shortening and deflection) against the elastica, relative to its length",
       "one static solve from rest"},
      {"bridge", "reference bridge under 100 N/m, pressed five thicknesses deep",
       "midspan deflection against the tie-beam solution of mid-plane stretching",
       "one static solve from rest"},
      {"pullin_cantilever", "pull-in of the reference cantilever over a 2 um gap",
       "pull-in voltage against a shooting solution of the beam equation", "one pull-in analysis"},
      {"pullin_bridge", "pull-in of the reference bridge over a 2 um gap, stretching",
       "pull-in voltage against a shooting solution with mid-plane stretching",
       "one pull-in analysis"},
      {"pullin_bridge_stretched",
       "pull-in of a 100 um bridge over a 4 um gap (twice its thickness), stretching",
       "pull-in voltage against a multiple-shooting solution with mid-plane stretching",
       "one pull-in analysis"},
      {"release", "reference cantilever released from a static tip deflection, undamped",
       "largest tip error over the first 1 ms against the exact modal series, relative to the "
       "initial deflection",
       "one time step; a tick is 1 ms of steps"},
  };
}

void RegisterSweep() {
  RegisterFrequencies();
  RegisterTipLoad(kTipSmall, {5, 10, 20, 50});
  RegisterTipLoad(kTipModerate, {5, 10, 20, 50});
  RegisterTipLoad(kElastica, {5, 10, 20, 50, 100, 200});
  RegisterBridge();
  RegisterPullIns();
  RegisterRelease();
}

std::string UtcNow() {
  const std::time_t now = std::time(nullptr);
  std::array<char, 32> buffer{};
  std::strftime(buffer.data(), buffer.size(), "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return buffer.data();
}

}  // namespace
}  // namespace cosmems

// Usage: accuracy_cost_bench [--report_dir=DIR] [Google Benchmark flags]. Writes
// DIR/accuracy_cost.csv and DIR/accuracy_cost.md once the benchmarks have run.
int main(int argc, char** argv) {
  using namespace cosmems;
  std::string report_dir = ".";
  std::string command = argv[0];
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    command += " " + arg;
    if (arg.rfind("--report_dir=", 0) == 0) {
      report_dir = arg.substr(std::string("--report_dir=").size());
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RegisterSweep();
  bench::AccuracyCostReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (reporter.rows().empty()) return 0;

  std::vector<bench::AccuracyCostRow> rows = reporter.rows();
  bench::NumberSeries(rows);
  bench::MarkParetoFront(rows);
  rows = bench::SortedForReport(rows, Problems());
  std::filesystem::create_directories(report_dir);
  const std::string csv = report_dir + "/accuracy_cost.csv";
  const std::string markdown = report_dir + "/accuracy_cost.md";
  const bench::ReportContext context{command, reporter.Machine(), UtcNow(), kTickBudgetUs};
  if (!bench::WriteCsv(csv, rows) || !bench::WriteMarkdown(markdown, rows, Problems(), context)) {
    std::fprintf(stderr, "accuracy_cost_bench: cannot write %s or %s\n", csv.c_str(),
                 markdown.c_str());
    return 1;
  }
  std::printf("wrote %s and %s\n", csv.c_str(), markdown.c_str());
  return 0;
}
