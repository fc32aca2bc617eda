// The Cosserat rod on the reference silicon cantilever in 3-D: one Newton iteration, a
// warm-started re-solve after a small load change (a haptic tick), a full static solve from rest,
// a dynamic step, the block-tridiagonal solver against the band Cholesky, and the elastica's
// accuracy against the element count with the solve time of each (the README's table).
//
// Every benchmark times each call on its own and reports the median and the maximum (counters
// p50_us and max_us; steady_clock's own cost, about 20 ns, is included) beside Google
// Benchmark's mean.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/analysis/step_timing.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/cosserat_newmark_integrator.hpp"
#include "reference_beam.hpp"
#include "rod/elastica.hpp"

namespace cosmems {
namespace {

constexpr double kLength = 200e-6;

double ReferenceEi() {
  return Material{169e9, 2330.0, 0.22}.young_modulus *
         RectangularSection{20e-6, 2e-6}.SecondMomentZ();
}

CosseratRod ReferenceRod(int elements, RodTheory theory = RodTheory::kSimoReissner) {
  CosseratOptions options;
  options.theory = theory;
  return CosseratRod(bench::ReferenceBeam(StructureKind::kCantilever, elements, 0), options);
}

// A dead tip force of alpha EI/L^2 toward the substrate (-y) with a tenth of it across the width
// (+z), so the solution is 3-D.
RodLoads TipForce(const CosseratRod& rod, double alpha) {
  const double force = alpha * ReferenceEi() / (kLength * kLength);
  return RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d(0.0, -force, 0.1 * force),
                         Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

// Runs `call` once per benchmark iteration, timing each call, and reports the median and max.
template <typename Call>
void TimeEachCall(benchmark::State& state, Call&& call) {
  std::vector<double> us;
  us.reserve(1 << 16);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    call();
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start)
                     .count());
  }
  const StepTiming timing = StepTiming::From(std::move(us));
  state.counters["p50_us"] = timing.median_us;
  state.counters["max_us"] = timing.max_us;
}

// One Newton iteration at a deflected state (PL^2/EI = 5): internal forces and tangent, loads,
// factorisation, solve and the multiplicative update. The state is the same every time, so
// every call does the full work.
void BM_NewtonIteration(benchmark::State& state) {
  const CosseratRod rod = ReferenceRod(static_cast<int>(state.range(0)));
  CosseratStaticSolver solver(rod);
  if (solver.Solve(TipForce(rod, 5.0)) != Status::kOk) state.SkipWithError("no equilibrium");
  RodLoads loads = RodLoads::None(rod.NodeCount());
  rod.ToInternal(TipForce(rod, 5.5), loads);
  BlockTridiagonalSystem system = rod.MakeSystem();
  CosseratRod::ElementKinematics kinematics = rod.MakeKinematics();
  Eigen::VectorXd residual(rod.DofCount());
  Eigen::Matrix3Xd correction(3, rod.NodeCount());
  const RodState start = solver.state();
  RodState next = start;
  TimeEachCall(state, [&] {
    rod.InternalForces(start, residual, kinematics);
    rod.InternalTangent(kinematics, system);
    rod.SubtractLoads(start, loads, residual, &system);
    rod.ClearSupported(residual);
    if (system.Factorize() != Status::kOk) state.SkipWithError("factorisation failed");
    residual = -residual;
    system.SolveInPlace(residual);
    rod.Retract(start, residual, 1.0, next, correction);
    benchmark::DoNotOptimize(next.displacement.data());
  });
  state.counters["dofs"] = rod.DofCount();
}
BENCHMARK(BM_NewtonIteration)
    ->Arg(10)
    ->Arg(20)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Unit(benchmark::kMicrosecond);

// The 50-element rod at equilibrium under PL^2/EI = 5, its forces and tangent assembled there.
struct AssembledRod {
  explicit AssembledRod(benchmark::State& state)
      : rod(ReferenceRod(50)),
        solver(rod),
        system(rod.MakeSystem()),
        kinematics(rod.MakeKinematics()),
        residual(rod.DofCount()) {
    if (solver.Solve(TipForce(rod, 5.0)) != Status::kOk) state.SkipWithError("no equilibrium");
    rod.InternalForces(solver.state(), residual, kinematics);
    rod.InternalTangent(kinematics, system);
  }
  CosseratRod rod;
  CosseratStaticSolver solver;
  BlockTridiagonalSystem system;
  CosseratRod::ElementKinematics kinematics;
  Eigen::VectorXd residual;
};

// The parts of that iteration, 50 elements.
void BM_NewtonIterationParts(benchmark::State& state) {
  AssembledRod at(state);
  const CosseratRod& rod = at.rod;
  const CosseratStaticSolver& solver = at.solver;
  BlockTridiagonalSystem& system = at.system;
  CosseratRod::ElementKinematics& kinematics = at.kinematics;
  Eigen::VectorXd& residual = at.residual;
  const BlockTridiagonalSystem assembled = system;
  switch (state.range(0)) {
    case 0:
      TimeEachCall(state, [&] { rod.InternalForces(solver.state(), residual, kinematics); });
      state.SetLabel("internal forces");
      break;
    case 1:
      TimeEachCall(state, [&] { rod.InternalTangent(kinematics, system); });
      state.SetLabel("tangent");
      break;
    case 2:
      TimeEachCall(state, [&] {
        system = assembled;
        if (system.Factorize() != Status::kOk) state.SkipWithError("factorisation failed");
      });
      state.SetLabel("copy + factorise");
      break;
    case 3:
      if (system.Factorize() != Status::kOk) state.SkipWithError("factorisation failed");
      TimeEachCall(state, [&] { system.SolveInPlace(residual); });
      state.SetLabel("solve");
      break;
    default: {
      RodState next = solver.state();
      Eigen::Matrix3Xd correction(3, rod.NodeCount());
      const Eigen::VectorXd increment = 1e-3 * Eigen::VectorXd::Ones(rod.DofCount());
      TimeEachCall(state, [&] { rod.Retract(solver.state(), increment, 1.0, next, correction); });
      state.SetLabel("update");
    }
  }
}
BENCHMARK(BM_NewtonIterationParts)->DenseRange(0, 4)->Unit(benchmark::kMicrosecond);

// The same matrix by BandCholesky (node-by-node band, supported rows removed: bandwidth 11),
// against the block-tridiagonal factorisation the rod uses.
void BM_BandCholeskyOfTheRodMatrix(benchmark::State& state) {
  const AssembledRod at(state);
  const Eigen::MatrixXd dense = at.system.ToDense();
  const int free = at.rod.DofCount() - 6;  // the clamp's six rows and columns go
  SymmetricBandMatrix band(free, 11);
  for (int j = 0; j < free; ++j) {
    for (int i = j; i <= std::min(free - 1, j + 11); ++i)
      band.mutable_data()(i - j, j) = dense(i + 6, j + 6);
  }
  BandCholesky cholesky;
  Eigen::VectorXd b = at.residual.tail(free);
  if (state.range(0) == 0) {
    TimeEachCall(state, [&] { cholesky.Compute(band); });
    state.SetLabel("factorise");
  } else {
    cholesky.Compute(band);
    TimeEachCall(state, [&] { cholesky.SolveInPlace(b); });
    state.SetLabel("solve");
  }
  if (cholesky.info() != Status::kOk) state.SkipWithError("factorisation failed");
}
BENCHMARK(BM_BandCholeskyOfTheRodMatrix)->DenseRange(0, 1)->Unit(benchmark::kMicrosecond);

// A haptic tick: re-solve from the last equilibrium after the tip force changed by 1 % (it
// alternates between PL^2/EI = 2 and 2.02, so every call moves).
void BM_WarmResolve(benchmark::State& state) {
  const CosseratRod rod = ReferenceRod(static_cast<int>(state.range(0)));
  CosseratStaticSolver solver(rod);
  const RodLoads a = TipForce(rod, 2.0);
  const RodLoads b = TipForce(rod, 2.02);
  if (solver.Solve(a) != Status::kOk) state.SkipWithError("no equilibrium");
  bool toward_b = true;
  long iterations = 0;
  TimeEachCall(state, [&] {
    if (solver.Solve(toward_b ? b : a) != Status::kOk) state.SkipWithError("re-solve failed");
    iterations += solver.last_stats().iterations;
    toward_b = !toward_b;
  });
  state.counters["iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_WarmResolve)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);

// The full static solve at PL^2/EI = 5 from the undeformed rod.
void BM_StaticSolveFromRest(benchmark::State& state) {
  const CosseratRod rod = ReferenceRod(static_cast<int>(state.range(0)));
  CosseratStaticSolver solver(rod);
  const RodLoads loads = TipForce(rod, 5.0);
  long iterations = 0;
  TimeEachCall(state, [&] {
    solver.Reset();
    if (solver.Solve(loads) != Status::kOk) state.SkipWithError("solve failed");
    iterations += solver.last_stats().iterations;
  });
  state.counters["iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
  state.counters["load_steps"] = solver.last_load_steps();
}
BENCHMARK(BM_StaticSolveFromRest)->Arg(20)->Arg(50)->Arg(100)->Unit(benchmark::kMicrosecond);

// One step (generalised-alpha, rho_inf = 0.9) of 1/100 of the first period, the rod swinging
// under a tip force of PL^2/EI = 1 switched on at t = 0.
void BM_DynamicStep(benchmark::State& state) {
  const CosseratRod rod = ReferenceRod(static_cast<int>(state.range(0)));
  const double f1 = 68.8e3;
  CosseratNewmarkIntegrator integrator(rod, GeneralizedAlphaParameters::FromSpectralRadius(0.9),
                                       1.0 / (100.0 * f1));
  const RodLoads loads = TipForce(rod, 1.0);
  if (integrator.Initialize(rod.UndeformedState(), RodLoads::None(rod.NodeCount())) !=
      Status::kOk) {
    state.SkipWithError("initialisation failed");
  }
  long iterations = 0;
  TimeEachCall(state, [&] {
    if (integrator.Step(loads) != Status::kOk) state.SkipWithError("step failed");
    iterations += integrator.last_stats().iterations;
  });
  state.counters["iterations"] =
      benchmark::Counter(static_cast<double>(iterations), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_DynamicStep)->Arg(20)->Arg(50)->Unit(benchmark::kMicrosecond);

// Accuracy against time: the tip under a dead vertical force PL^2/EI = 5 against the elastica,
// for the Kirchhoff limit and the physical (shear-deformable) rod, solved from rest.
void BM_ElasticaAccuracy(benchmark::State& state) {
  const auto theory = static_cast<RodTheory>(state.range(1));
  const CosseratRod rod = ReferenceRod(static_cast<int>(state.range(0)), theory);
  const double force = 5.0 * ReferenceEi() / (kLength * kLength);
  const RodLoads loads = RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d(0.0, -force, 0.0),
                                         Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  CosseratStaticSolver solver(rod);
  TimeEachCall(state, [&] {
    solver.Reset();
    if (solver.Solve(loads) != Status::kOk) state.SkipWithError("solve failed");
  });
  const test::ElasticaTip exact = test::Elastica(5.0);
  const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / kLength;
  state.counters["err_shortening"] = std::abs(-tip.x() - exact.shortening);
  state.counters["err_deflection"] = std::abs(-tip.y() - exact.deflection);
  state.counters["err_angle"] = std::abs(rod.TipRotation(solver.state()).z() + exact.angle);
  state.SetLabel(theory == RodTheory::kKirchhoff ? "kirchhoff" : "simo-reissner");
}
BENCHMARK(BM_ElasticaAccuracy)
    ->ArgsProduct({{5, 10, 20, 50, 100, 200},
                   {static_cast<int>(RodTheory::kKirchhoff),
                    static_cast<int>(RodTheory::kSimoReissner)}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace cosmems
