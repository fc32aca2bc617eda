// Hard cases of the surface forces: the electrostatic voltage a millionth either side of pull-in
// (the cantilever, and the strongly stretched bridge), the Casimir and van der Waals pressures at
// a 1 nm gap, stiff contact advanced in 1 ms steps, and 10^3 stick-release cycles (10^5 in
// bench/hard_cases_bench.cpp). Each case ends converged, with its known answer, or with a status
// saying why not; never with a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>

#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/beam/force_tuple.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "haptics/haptic_test_beam.hpp"
#include "hard_cases/hard_case_support.hpp"
#include "hard_cases/stick_release_cycles.hpp"
#include "modal_reduction.hpp"
#include "no_force.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

constexpr double kL = test::kReferenceLength;
constexpr double kGap = test::kReferenceGap;

// No structural force: the pressures alone, ramped with the loads.
using test::NoForce;

// ---------------------------------------------------------------------------------------------
// The voltage at V_PI (1 -+ 1e-6): the reference cantilever, and the strongly stretched bridge
// (100 um long, 2 um thick over 4 and 20 um gaps: the stretching stiffens its path until the fold
// sits at 0.56 and 0.65 of the gap, at 1.28 and 4.4 times the linear bridge's voltage).

struct PullInEdgeCase {
  const char* name;
  StructureKind kind;
  double length, gap;
  bool stretching;
};

std::string EdgeCaseName(const ::testing::TestParamInfo<PullInEdgeCase>& info) {
  return info.param.name;
}

class PullInEdgeTest : public ::testing::TestWithParam<PullInEdgeCase> {
 protected:
  // A slope tolerance of 1e-7 puts the fold's voltage within ~1e-14 of the model's own and its
  // travel within ~1e-7 of the gap (the quadratic model's error is the square of the slope
  // left, in the load): far inside the 1e-6 the cases sit from it.
  void SetUp() override {
    const PullInEdgeCase& c = GetParam();
    model_.emplace(
        MakeStructure(c.kind, c.length, test::Silicon(), test::ReferenceSection(), 20, 1));
    if (c.stretching) stretching_.emplace(*model_);
    options_.electrode = {c.gap, 0.0, c.length};
    options_.control_x = c.kind == StructureKind::kBridge ? 0.5 * c.length : c.length;
    options_.fold.slope_tolerance = 1e-7;
    fold_ = SolvePullIn(*model_, options_, Structural());
    ASSERT_EQ(fold_.status, Status::kOk);
  }

  NonlinearForce* Structural() { return stretching_ ? &*stretching_ : nullptr; }

  // The static equilibrium under the voltage V_PI (1 + relative), the pressure ramped from zero.
  NonlinearStaticSolution StaticAt(double relative) {
    GapForce<2, ElectrostaticPressure> pressure(
        *model_, ElectrostaticPressure{fold_.voltage_v * (1.0 + relative), 20e-6, false},
        options_.electrode);
    NoForce none;
    NonlinearForce& structural = stretching_ ? static_cast<NonlinearForce&>(*stretching_) : none;
    return SolveNonlinearStatic(*model_, structural, LoadCase{}, {}, &pressure);
  }

  double Travel(const Eigen::VectorXd& d) const {  // toward the substrate, of the gap
    return -OutputPoint::DeflectionAt(*model_, options_.control_x).Evaluate(d) / GetParam().gap;
  }

  std::optional<BeamModel<2>> model_;
  std::optional<StretchingForce<2>> stretching_;
  PullInOptions options_;
  PullInResult fold_;
};

// Below a fold the equilibrium stands off it by the square root of the load's shortfall:
// lambda* - lambda = c (s* - s)^2 with lambda = V^2, so 4e-6 below V_PI stands twice as far off
// as 1e-6 below. The next term of the expansion is of relative order sqrt(1e-6) (measured ratio
// 2.000), and the fold's travel is known to 1e-7 of the gap against stand-offs of 7e-4: 1 %
// holds both.
TEST_P(PullInEdgeTest, JustBelowPullInTheBeamHoldsShortOfTheFoldOnItsSquareRootLaw) {
  const double fold_travel = fold_.travel_m / GetParam().gap;
  double distance[2] = {0.0, 0.0};
  int i = 0;
  for (double below : {1e-6, 4e-6}) {
    const NonlinearStaticSolution solution = StaticAt(-below);
    ASSERT_EQ(solution.status, Status::kOk) << below;
    ASSERT_TRUE(solution.displacement.allFinite());
    const double travel = Travel(solution.displacement);
    EXPECT_LT(travel, fold_travel) << below;
    distance[i++] = fold_travel - travel;
    test::RecordFigure("newton_iterations_" + std::to_string(i), solution.iterations);
  }
  EXPECT_GT(distance[0], 0.0);
  EXPECT_NEAR(distance[1] / distance[0], 2.0, 0.02);
  test::RecordFigure("fold_travel", fold_travel);
  test::RecordFigure("stand_off_at_1e-6", distance[0]);
  test::RecordFigure("stand_off_ratio", distance[1] / distance[0]);
}

// Past the fold no equilibrium is left short of the substrate: the ramp stops where its matrix
// turns indefinite, with the last stable state kept (what the CLI reports as collapsed).
TEST_P(PullInEdgeTest, JustAbovePullInTheRampStopsAtTheFoldAndSaysSo) {
  const NonlinearStaticSolution solution = StaticAt(1e-6);
  EXPECT_EQ(solution.status, Status::kNotPositiveDefinite);
  EXPECT_LT(solution.load_factor, 1.0);
  // The load steps halve down to 1/1024 of the load: the last one accepted lies within that.
  EXPECT_GE(solution.load_factor, 1.0 - 1.0 / 1024.0);
  ASSERT_TRUE(solution.displacement.allFinite());
  EXPECT_LT(Travel(solution.displacement), fold_.travel_m / GetParam().gap);
  test::RecordFigure("newton_iterations", solution.iterations);
  test::RecordFigure("load_factor", solution.load_factor);
}

// A voltage bound a millionth below V_PI ends the search with kNotConverged (no fold below the
// bound); a millionth above it, the search finds the same fold.
TEST_P(PullInEdgeTest, AVoltageBoundAMillionthEitherSideOfPullInIsHonoured) {
  PullInOptions bounded = options_;
  const double v = fold_.voltage_v;
  bounded.fold.max_load = std::pow(v * (1.0 - 1e-6), 2);
  const PullInResult below = SolvePullIn(*model_, bounded, Structural());
  EXPECT_EQ(below.status, Status::kNotConverged);
  EXPECT_TRUE(below.displacement.allFinite());
  bounded.fold.max_load = std::pow(v * (1.0 + 1e-6), 2);
  const PullInResult above = SolvePullIn(*model_, bounded, Structural());
  ASSERT_EQ(above.status, Status::kOk);
  EXPECT_NEAR(above.voltage_v, v, 1e-12 * v);  // the same solves: the same fold
}

INSTANTIATE_TEST_SUITE_P(
    Beams, PullInEdgeTest,
    ::testing::Values(
        PullInEdgeCase{"Cantilever", StructureKind::kCantilever, kL, kGap, false},
        PullInEdgeCase{"StretchedBridgeGap2t", StructureKind::kBridge, 100e-6, 4e-6, true},
        PullInEdgeCase{"StretchedBridgeGap10t", StructureKind::kBridge, 100e-6, 20e-6, true}),
    EdgeCaseName);

// ---------------------------------------------------------------------------------------------
// The Casimir and van der Waals pressures at a 1 nm gap.

enum class Pressure { kCasimir, kVanDerWaals };

struct OneNanometreCase {
  Pressure pressure;
  int exponent;  ///< p ~ 1 / d^exponent
};

std::string PressureName(const ::testing::TestParamInfo<OneNanometreCase>& info) {
  return info.param.pressure == Pressure::kCasimir ? "Casimir" : "VanDerWaals";
}

class OneNanometreGapTest : public ::testing::TestWithParam<OneNanometreCase> {
 protected:
  template <typename P>
  void Check(const P& pressure) {
    const BeamModel<2> model = test::ReferenceCantilever(20, 1);
    ExpectCollapseScalesWithTheGap(model, pressure);
    ExpectTheStaticRampRefuses(model, pressure);
    ExpectTheFirstStepRefusesAndKeepsTheState(model, pressure);
    ExpectAPressOntoTheSubstrateHoldsOrStopsClearly(pressure);
  }

  // The collapse (the largest multiple of the pressure the beam withstands) in units of the gap
  // is one problem at every gap: its multiple scales as g^(n+1). The same solves in the same
  // internal numbers leave only round-off between them (measured 3e-12).
  template <typename P>
  void ExpectCollapseScalesWithTheGap(const BeamModel<2>& model, const P& pressure) {
    double scale[2] = {0.0, 0.0};
    int i = 0;
    for (double gap : {kGap, 1e-9}) {
      PullInOptions options;
      options.electrode = {gap, 0.0, kL};
      options.control_x = kL;
      const PullInResult fold = SolveFold(model, pressure, options);
      ASSERT_EQ(fold.status, Status::kOk) << gap;
      scale[i++] = fold.scale;
    }
    const double expected = scale[0] * std::pow(1e-9 / kGap, GetParam().exponent + 1);
    EXPECT_NEAR(scale[1], expected, 1e-9 * expected);
    test::RecordFigure("collapse_scale_at_1nm", scale[1]);
    test::RecordFigure("scaling_error", scale[1] / expected - 1.0);
    EXPECT_LT(scale[1], 1e-7);  // at 1 nm the beam cannot hold a ten-millionth of the pressure
  }

  // Ramped in from zero, the pressure at 1 nm collapses the beam at every load step down to
  // 1/1024 of it: the first Newton matrix is already indefinite.
  template <typename P>
  void ExpectTheStaticRampRefuses(const BeamModel<2>& model, const P& pressure) {
    GapForce<2, P> force(model, pressure, GapSpan{1e-9, 0.0, kL});
    NoForce none;
    const NonlinearStaticSolution solution =
        SolveNonlinearStatic(model, none, LoadCase{}, {}, &force);
    EXPECT_EQ(solution.status, Status::kNotPositiveDefinite);
    EXPECT_EQ(solution.load_factor, 0.0);
    EXPECT_EQ(solution.displacement.norm(), 0.0);  // the unloaded beam, kept
  }

  // Switched on at rest, it snaps the beam within every step down to 2^-8 of 1 us: each
  // predictor closes the gap somewhere, outside the pressure's domain; Newton from the step's
  // start instead meets a matrix the pressure's stiffness leaves indefinite under every mass
  // shift, and the step is refused as such, with the state left at its start.
  template <typename P>
  void ExpectTheFirstStepRefusesAndKeepsTheState(const BeamModel<2>& model, const P& pressure) {
    GapForce<2, P> force(model, pressure, GapSpan{1e-9, 0.0, kL});
    NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, force,
                                          GeneralizedAlphaParameters::FromSpectralRadius(0.6),
                                          1e-6 / model.units().time);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.FreeDofCount());
    ASSERT_EQ(integrator.Initialize(zero, zero, zero), Status::kOk);
    EXPECT_EQ(integrator.Step(zero), Status::kNotPositiveDefinite);
    EXPECT_EQ(integrator.last_stats().cuts, NewtonOptions{}.max_cuts);
    EXPECT_EQ(integrator.displacement().norm(), 0.0);
    EXPECT_EQ(integrator.velocity().norm(), 0.0);
    test::RecordFigure("iterations_of_the_refused_step", integrator.last_stats().evaluations);
  }

  // A substrate 2 um down whose contact plane stands 1 nm off it, the tip pushed down by three
  // times the force that closes the gap in 100 us steps: the contact holds the beam, every state
  // finite and clear of the substrate, under the van der Waals pressure there (5 MPa) and the
  // Casimir pressure (1.3 GPa). The pressures keep their value on the contact plane below it
  // (GapSpan::separation); while the Casimir pressure still grew through the penetration the
  // penalty allows, its step matrix stayed indefinite under any mass shift (kNotPositiveDefinite).
  template <typename P>
  void ExpectAPressOntoTheSubstrateHoldsOrStopsClearly(const P& pressure) {
    const BeamModel<2> model = test::ReferenceCantilever(20, 0);
    ContactOptions contact;
    contact.gap = kGap;
    contact.separation = 1e-9;
    ForceTuple<SubstrateContact<2>, GapForce<2, P>> forces(
        SubstrateContact<2>(model, contact),
        GapForce<2, P>(model, pressure, GapSpan{kGap, 0.0, kL}.WithSeparation(contact.separation)));
    NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, forces,
                                          GeneralizedAlphaParameters::FromSpectralRadius(0.0),
                                          1e-4 / model.units().time);
    const int n = model.FreeDofCount();
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    ASSERT_EQ(integrator.Initialize(f, f, f), Status::kOk);
    const int tip = model.dofs().Reduced(20, NodalDof::kUy);
    Status status = Status::kOk;
    int step = 0;
    for (; step < 100 && status == Status::kOk; ++step) {
      f[tip] = -3.0 * test::ReferenceTipStiffness() * kGap * std::min(1.0, step / 30.0) /
               model.units().force;
      status = integrator.Step(f);
      ASSERT_TRUE(integrator.displacement().allFinite()) << step;
    }
    EXPECT_EQ(status, Status::kOk) << "at step " << step;
    const double tip_m = integrator.displacement()[tip] * model.units().length;
    EXPECT_GT(tip_m, -kGap);
    test::RecordFigure("refused_at_step", step);
  }
};

TEST_P(OneNanometreGapTest, CollapsesOrRefusesWithAStatusNeverANaN) {
  if (GetParam().pressure == Pressure::kCasimir) {
    Check(CasimirPressure{});
  } else {
    Check(VanDerWaalsPressure{1e-19});  // a Hamaker constant of silicon's order
  }
}

INSTANTIATE_TEST_SUITE_P(Pressures, OneNanometreGapTest,
                         ::testing::Values(OneNanometreCase{Pressure::kCasimir, 4},
                                           OneNanometreCase{Pressure::kVanDerWaals, 3}),
                         PressureName);

// ---------------------------------------------------------------------------------------------
// Stiff contact in 1 ms steps.

enum class Surface { kContact, kStiction, kStictionAndCasimir };

struct StiffContactCase {
  Surface surface;
  double time_step;    ///< s
  bool modal = false;  ///< 4 modes (NonlinearModalIntegrator) instead of the full model
};

std::string SurfaceName(const ::testing::TestParamInfo<StiffContactCase>& info) {
  const char* names[] = {"Contact", "Stiction", "StictionAndCasimir"};
  return std::string(names[static_cast<int>(info.param.surface)]) +
         (info.param.time_step > 5e-4 ? "In1msSteps" : "In100usSteps") +
         (info.param.modal ? "OnFourModes" : "");
}

class StiffContactTest : public ::testing::TestWithParam<StiffContactCase> {};

// The hand's tip force over a cycle of 50 ms: down to three times the force that closes the gap,
// held, up to five times that force the other way (which peels a stuck tip off), then none.
double HandForce(double t) {
  const double closing = test::ReferenceTipStiffness() * kGap;
  const double s = std::fmod(t, 0.05) / 0.05;
  if (s < 0.3) return -3.0 * closing * s / 0.3;
  if (s < 0.5) return -3.0 * closing;
  if (s < 0.8) return -3.0 * closing + 8.0 * closing * (s - 0.5) / 0.3;
  return 0.0;
}

// The reference cantilever pressed onto the substrate (3 closing forces) and pulled off (5 the
// other way: the tip, stuck alone, lets go near 3, where its energy release rate p^2 theta / b
// reaches Gamma) three times by the hand, in
// steps of 1 ms (69 periods of its first mode, the servo tick as one step) or 100 us (the haptic
// path's substeps). Every step converges, every press sticks the tip and every pull frees it,
// with the Casimir pressure too: its snap-in turns the 1 ms step matrix indefinite, and Newton
// then raises the matrix's mass term until it is definite (before, 70 of the 150 steps were
// refused after 8 halvings and the tip stayed stuck). Every accepted state keeps the contact's
// tolerance, and the energy stays within the static energy of the largest hand force F on the free
// tip, F^2 / (2k): the substrate only takes energy away, and so does generalised-alpha at rho_inf =
// 0 over steps of 7 periods and more, whose inertia term is 1 / (w1 h)^2 < 5e-4 of the stiffness; 1
// % covers that and the Casimir pressure's work at the 20 nm separation. Measured: F^2 / (2k) to
// 1e-6 at the peak of the pull, which the free tip holds statically. The modal path (4 modes,
// the force held over each step) meets the same bounds with its modes damped at Q = 10, gone
// within a step as rho_inf = 0 leaves nothing of them: undamped, exact propagation keeps the
// freed beam ringing, so it touches down again (5 contacts instead of 3) and the Casimir pressure
// turns more of its work into motion (6 % over the bound).
TEST_P(StiffContactTest, PressAndPullOffThreeTimesWithinTheToleranceAndTheEnergyBound) {
  // Named copies, not a structured binding: clang 14 (the sanitizer build) cannot capture one.
  const Surface surface = GetParam().surface;
  const double time_step = GetParam().time_step;
  const bool modal = GetParam().modal;
  const BeamModel<2> model = test::ReferenceCantilever(20, 0);
  ContactOptions options;
  options.gap = kGap;
  if (surface != Surface::kContact) {
    options.stiction = true;
    options.adhesion_energy = 0.02;
  }
  if (surface == Surface::kStictionAndCasimir) options.separation = 2e-8;
  SubstrateContact<2> contact(model, options);
  GapForce<2, CasimirPressure> casimir(model, CasimirPressure{},
                                       GapSpan{kGap, 0.0, kL}.WithSeparation(options.separation));
  ForceSum forces;
  forces.Add(contact);
  if (surface == Surface::kStictionAndCasimir) forces.Add(casimir);
  const double dt = time_step / model.units().time;
  const int n = model.FreeDofCount();
  const int tip = model.dofs().Reduced(20, NodalDof::kUy);
  Eigen::VectorXd pattern = Eigen::VectorXd::Zero(n), mv(n), kd(n);
  pattern[tip] = 1.0 / model.units().force;  // 1 N at the tip
  const double force_max = 5.0 * test::ReferenceTipStiffness() * kGap;
  const double bound = 1.01 * force_max * force_max / (2.0 * test::ReferenceTipStiffness());
  const long steps = std::lround(0.15 / time_step);
  long refused = 0, cuts = 0, iterations = 0;
  double largest = 0.0;
  // `step(integrator, hand force in N)` on either path.
  auto run = [&](auto& integrator, auto&& step) {
    for (long i = 1; i <= steps; ++i) {
      const Status status = step(integrator, HandForce(static_cast<double>(i) * time_step));
      cuts += integrator.last_stats().cuts;
      iterations += integrator.last_stats().evaluations;
      if (status != Status::kOk) {
        ++refused;
        EXPECT_EQ(status, Status::kNotPositiveDefinite) << "step " << i;
      }
      const Eigen::VectorXd& d = integrator.displacement();
      const Eigen::VectorXd& v = integrator.velocity();
      ASSERT_TRUE(d.allFinite() && v.allFinite()) << "step " << i;
      EXPECT_LE(contact.Penetration(d), contact.tolerance()) << "step " << i;
      model.Mass(0).Multiply(v, mv);
      model.Stiffness().Multiply(d, kd);
      largest = std::max(
          largest, 0.5 * (v.dot(mv) + d.dot(kd)) * model.units().force * model.units().length);
    }
  };
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  if (modal) {
    NonlinearModalIntegrator integrator(
        model, test::ModalReduction(model, 4, DampingModel::QualityFactor(10.0)), pattern, forces,
        dt);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(1);
    ASSERT_EQ(integrator.Initialize(zero, zero, s), Status::kOk);
    run(integrator, [&](NonlinearModalIntegrator& path, double force) {
      s[0] = force;
      return path.Step(s);
    });
  } else {
    NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, forces,
                                          GeneralizedAlphaParameters::FromSpectralRadius(0.0), dt);
    ASSERT_EQ(integrator.Initialize(zero, zero, zero), Status::kOk);
    Eigen::VectorXd f(n);
    run(integrator, [&](NonlinearNewmarkIntegrator& path, double force) {
      f = force * pattern;
      return path.Step(f);
    });
  }
  EXPECT_LE(largest, bound);
  const ContactEvents& events = contact.events();
  EXPECT_EQ(refused, 0);
  EXPECT_EQ(events.contacts, 3);
  EXPECT_EQ(events.stuck, surface == Surface::kContact ? 0 : 3);
  EXPECT_EQ(events.releases, events.stuck);
  test::RecordFigure("refused_steps", refused);
  test::RecordFigure("cuts", cuts);
  test::RecordFigure("newton_iterations", iterations);
  test::RecordFigure("largest_energy_of_bound", largest / bound);
  test::RecordFigure("stuck", events.stuck);
  test::RecordFigure("releases", events.releases);
}

INSTANTIATE_TEST_SUITE_P(
    Surfaces, StiffContactTest,
    ::testing::Values(StiffContactCase{Surface::kContact, 1e-3},
                      StiffContactCase{Surface::kStiction, 1e-3},
                      StiffContactCase{Surface::kStictionAndCasimir, 1e-3},
                      StiffContactCase{Surface::kStictionAndCasimir, 1e-4},
                      StiffContactCase{Surface::kContact, 1e-3, true},
                      StiffContactCase{Surface::kStiction, 1e-3, true},
                      StiffContactCase{Surface::kStictionAndCasimir, 1e-3, true},
                      StiffContactCase{Surface::kStictionAndCasimir, 1e-4, true}),
    SurfaceName);

// ---------------------------------------------------------------------------------------------
// Stick-release cycles.

// 10^3 cycles (10^5 in the bench) of the 10-element reference cantilever. No drift: every cycle
// sticks once and comes free once, its S shape has the same span, and it ends where the first
// ended and reaches the same largest energy to round-off (the cycles start from rest, and
// rho_inf = 0 over steps of seven periods leaves the next cycle nothing of the last: measured
// 7e-22 m and 4e-13 relative). The S shape's free span is the energy release rate's,
// (3 E t^3 g^2 / (2 Gamma))^(1/4) = 142 um, within 1.5 elements (the edge of contact moves a
// node at a time; see the contact tests). The largest energy is the released beam's under the
// full lift load, the free cantilever's q^2 L^5 / (40 EI) (10 Hermite elements hold it to 3e-6);
// 1 % allows the lag of the quasi-static response, of order 1 / (w1 h)^2 = 5e-4 (measured
// 0.9991 of it).
TEST(StickReleaseTest, AThousandCyclesStickAndReleaseOnceEachWithoutDrift) {
  constexpr long kCycles = 1000;
  const test::StickReleaseRun run = test::RunStickReleaseCycles(10, kCycles);
  ASSERT_EQ(run.status, Status::kOk);
  EXPECT_TRUE(run.finite);
  EXPECT_EQ(run.cycles, kCycles);
  EXPECT_EQ(run.events.stuck, kCycles);
  EXPECT_EQ(run.events.releases, kCycles);
  const RectangularSection s = test::ReferenceSection();
  const double span = std::pow(3.0 * test::Silicon().young_modulus * std::pow(s.thickness, 3) *
                                   kGap * kGap / (2.0 * test::kCycleAdhesion),
                               0.25);
  EXPECT_NEAR(run.first_span_m, span, 1.5 * kL / 10);
  EXPECT_EQ(run.span_drift_m, 0.0);
  EXPECT_LE(run.end_drift_m, 1e-12 * kGap);
  EXPECT_NEAR(run.max_energy_j, run.first_max_energy_j, 1e-9 * run.first_max_energy_j);
  EXPECT_NEAR(run.min_cycle_max_energy_j, run.first_max_energy_j, 1e-9 * run.first_max_energy_j);
  EXPECT_GT(run.max_energy_j, 0.99 * run.lift_energy_j);
  EXPECT_LT(run.max_energy_j, 1.01 * run.lift_energy_j);
  test::RecordFigure("newton_iterations_per_step",
                     static_cast<double>(run.iterations) / static_cast<double>(run.steps));
  test::RecordFigure("cuts", run.cuts);
  test::RecordFigure("span_um", 1e6 * run.first_span_m);
  test::RecordFigure("end_drift_m", run.end_drift_m);
  test::RecordFigure("max_energy_over_first_minus_1",
                     run.max_energy_j / run.first_max_energy_j - 1.0);
  test::RecordFigure("max_energy_over_lift", run.max_energy_j / run.lift_energy_j);
}

}  // namespace
}  // namespace cosmems
