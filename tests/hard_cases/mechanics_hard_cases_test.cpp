// Hard cases of the beam and the rod: slenderness from 5 to 10^4 (a 100 nm thick nanobeam and a
// 5 mm long beam among them), 1 to 1000 elements, an axial load a millionth short of buckling,
// the elastica up to PL^2/EI = 20 and the end moment that rolls the rod into a full circle. Each
// against its closed form, with a tolerance that says what is left: discretisation or round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/buckling_analysis.hpp"
#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/analysis/static_analysis.hpp"
#include "hard_cases/hard_case_support.hpp"
#include "rod/elastica.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::StiffnessRoundOff;

double BendingStiffness(const RectangularSection& s) {
  return test::Silicon().young_modulus * s.SecondMomentZ();
}

// ---------------------------------------------------------------------------------------------
// Slenderness from 5 to 10^4.

struct Geometry {
  const char* name;
  double length, width, thickness;  ///< m
};

std::string GeometryName(const ::testing::TestParamInfo<Geometry>& info) { return info.param.name; }

class SlendernessTest : public ::testing::TestWithParam<Geometry> {
 protected:
  BeamModel<2> Model(int order) const {
    const Geometry& g = GetParam();
    return BeamModel<2>(MakeStructure(StructureKind::kCantilever, g.length, test::Silicon(),
                                      {g.width, g.thickness}, 20, order));
  }
};

// A tip force bends every one of them by P L^3 / 3EI: Hermite elements are exact at the nodes
// for a tip load, and the internal units make the same problem the same numbers at every size,
// so only round-off remains (StiffnessRoundOff(20) = 3.5e-11; measured at most 1e-11).
TEST_P(SlendernessTest, TipForceBendsItByPL3Over3EI) {
  const Geometry& g = GetParam();
  const BeamModel<2> model = Model(1);
  const double ei = BendingStiffness({g.width, g.thickness});
  const double force = -1e-3 * ei / (g.length * g.length);
  LoadCase loads;
  loads.points.push_back({g.length, Eigen::Vector3d(0.0, force, 0.0), Eigen::Vector3d::Zero()});
  const StaticSolution solution = SolveStatic(model, loads);
  ASSERT_EQ(solution.status, Status::kOk);
  const double exact = force * std::pow(g.length, 3) / (3.0 * ei);
  const double tip = BeamField<2>(model, solution.displacement).At(g.length)[1];
  EXPECT_NEAR(tip, exact, StiffnessRoundOff(20) * std::abs(exact));
  test::RecordFigure("relative_error", tip / exact - 1.0);
}

// The first three bending frequencies against the roots of cos x cosh x = -1, picked out by
// their labels from among the axial modes, which at L/t = 5 fall between them (the first axial
// mode lies between bending modes 2 and 3). The model is Euler-Bernoulli's whatever the
// slenderness, so the roots are its exact answer: 20 elements of series order 1 leave 1e-12,
// 1.3e-11 and 7.7e-10 on the reference cantilever (README); 1e-8 is ten times the third.
TEST_P(SlendernessTest, BendingFrequenciesMatchTheEulerBernoulliRootsAmongAxialModes) {
  const Geometry& g = GetParam();
  const BeamModel<2> model = Model(1);
  ModalOptions options;
  options.count = 6;  // three bending modes and, when stubby, the axial ones between them
  const ModalResult result = SolveModal(model, options);
  ASSERT_EQ(result.status, Status::kOk);
  const RectangularSection section{g.width, g.thickness};
  const double rho_a = test::Silicon().density * section.Area();
  int bending = 0, other = 0;
  for (const Mode& mode : result.modes) {
    ASSERT_TRUE(std::isfinite(mode.frequency_hz));
    if (mode.kind != ModeKind::kBendingY) {
      ++other;
      continue;
    }
    if (++bending > 3) break;
    const double exact = test::BendingFrequency(test::FrequencyRoot(bending, -1.0), g.length,
                                                BendingStiffness(section), rho_a);
    EXPECT_NEAR(mode.frequency_hz, exact, 1e-8 * exact) << "bending mode " << bending;
    test::RecordFigure("mode_" + std::to_string(bending) + "_error",
                       mode.frequency_hz / exact - 1.0);
  }
  EXPECT_GE(bending, 3);
  test::RecordFigure("axial_modes_among_the_first_six", other);
}

// Pull-in over a gap of one thickness: V_PI / sqrt(E t^3 g^3 / (eps0 L^4)) is the same number
// for every geometry (the problem in units of L and g is one), Osterberg's sqrt(0.28) to its
// two digits. The solves in those units are the same, so only round-off separates them: a few
// ulps a solve over 14 solves (measured at most 4.3e-12).
TEST_P(SlendernessTest, PullInVoltageFollowsItsSimilarityLaw) {
  const Geometry& g = GetParam();
  auto normalised = [](const Geometry& geometry) {
    const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, geometry.length,
                                           test::Silicon(), {geometry.width, geometry.thickness},
                                           20, 1));
    PullInOptions options;
    options.electrode = {geometry.thickness, 0.0, geometry.length};
    options.control_x = geometry.length;
    const PullInResult result = SolvePullIn(model, options);
    EXPECT_EQ(result.status, Status::kOk) << geometry.name;
    const double t3g3 = std::pow(geometry.thickness, 6);
    return result.voltage_v / std::sqrt(test::Silicon().young_modulus * t3g3 /
                                        (kVacuumPermittivity * std::pow(geometry.length, 4)));
  };
  const double reference = normalised({"reference", 200e-6, 20e-6, 2e-6});
  EXPECT_NEAR(reference, std::sqrt(0.28), 5e-3 * std::sqrt(0.28));
  const double value = normalised(g);
  EXPECT_NEAR(value, reference, 1e-10 * reference);
  test::RecordFigure("normalised_pullin", value);
  test::RecordFigure("difference_from_reference", value / reference - 1.0);
}

INSTANTIATE_TEST_SUITE_P(FromStubbyToThread, SlendernessTest,
                         ::testing::Values(Geometry{"Stubby_L_over_t_5", 10e-6, 20e-6, 2e-6},
                                           Geometry{"Reference_100", 200e-6, 20e-6, 2e-6},
                                           Geometry{"Nanobeam_100nm_thick_200", 20e-6, 1e-6,
                                                    100e-9},
                                           Geometry{"FiveMillimetresLong_2500", 5e-3, 20e-6, 2e-6},
                                           Geometry{"Thread_10000", 1e-3, 1e-6, 100e-9}),
                         GeometryName);

// ---------------------------------------------------------------------------------------------
// 1 to 1000 elements.

class ElementCountTest : public ::testing::TestWithParam<int> {
 protected:
  BeamModel<2> Model(int order) const { return test::ReferenceCantilever(GetParam(), order); }
};

// Statics exact at the nodes to round-off (64 eps for the few operations of a coarse mesh,
// StiffnessRoundOff for a fine one), the first frequency converging as h^8 (series order 1;
// 1.1e-4 with one element) down to round-off, Euler's buckling load as h^4 (7.5e-3 with one
// element, the classical Hermite result 2.4865 EI/L^2 against pi^2/4) down to round-off. With
// one and two elements the buckling analysis used to report kNotConverged: its subspace was
// wider than the unknowns G_0 acts on.
TEST_P(ElementCountTest, StaticModalAndBucklingAnswersConvergeToRoundOff) {
  const int n = GetParam();
  const double l = test::kReferenceLength, ei = test::Eiz();
  const BeamModel<2> model = Model(1);
  LoadCase loads;
  loads.points.push_back({l, Eigen::Vector3d(0.0, -1e-7, 0.0), Eigen::Vector3d::Zero()});
  const StaticSolution solution = SolveStatic(model, loads);
  ASSERT_EQ(solution.status, Status::kOk);
  const double tip = -1e-7 * l * l * l / (3.0 * ei);
  const double computed = BeamField<2>(model, solution.displacement).At(l)[1];
  EXPECT_NEAR(computed, tip, (64.0 * test::kMachineEpsilon + StiffnessRoundOff(n)) * std::abs(tip));
  test::RecordFigure("static_error", computed / tip - 1.0);

  ModalOptions one;
  one.count = 1;
  const ModalResult modes = SolveModal(model, one);
  ASSERT_EQ(modes.status, Status::kOk);
  const double f1 =
      test::BendingFrequency(test::FrequencyRoot(1, -1.0), l, ei,
                             test::Silicon().density * test::ReferenceSection().Area());
  EXPECT_NEAR(modes.modes.at(0).frequency_hz, f1,
              (2e-4 * std::pow(n, -8.0) + StiffnessRoundOff(n)) * f1);
  test::RecordFigure("frequency_error", modes.modes.at(0).frequency_hz / f1 - 1.0);

  const BucklingResult buckling = SolveBuckling(model);
  ASSERT_EQ(buckling.status, Status::kOk);
  const double euler = kPi * kPi * ei / (4.0 * l * l);
  EXPECT_NEAR(buckling.modes.at(0).critical_load_n, euler,
              (1e-2 * std::pow(n, -4.0) + StiffnessRoundOff(n)) * euler);
  test::RecordFigure("buckling_error", buckling.modes.at(0).critical_load_n / euler - 1.0);
}

// Pull-in by displacement control converges at every mesh: below 100 elements Newton meets its
// relative tolerance, above it the residual stops at the rounding floor of K d, which the
// solvers accept (SymmetricBandMatrix::ProductRoundOff). The voltage converges as h^4 with a
// constant below 0.015 (measured 3.5e-3 with one element, 6.3e-3 with two, 8e-3 from 13 on) to
// the 40-element value, itself within 0.015 / 40^4 of the limit, down to round-off. The surface
// forces' span, the nominal length, lies a few ulps past the sum of the element lengths for some
// counts (13 elements end 8e-20 m short): it is accepted.
TEST_P(ElementCountTest, PullInConvergesAndSurfaceForcesSpanTheBeamAtEveryCount) {
  const int n = GetParam();
  const double l = test::kReferenceLength, gap = test::kReferenceGap;
  auto pull_in = [&](int elements) {
    const BeamModel<2> model = test::ReferenceCantilever(elements, 1);
    PullInOptions options;
    options.electrode = {gap, 0.0, l};
    options.control_x = l;
    return SolvePullIn(model, options);
  };
  const PullInResult reference = pull_in(40);
  const PullInResult result = pull_in(n);
  ASSERT_EQ(result.status, Status::kOk);
  const double discretisation = 0.015 * (std::pow(n, -4.0) + std::pow(40.0, -4.0));
  EXPECT_NEAR(result.voltage_v, reference.voltage_v,
              (discretisation + StiffnessRoundOff(n)) * reference.voltage_v);
  EXPECT_LT(result.solves, 20);
  test::RecordFigure("voltage_error", result.voltage_v / reference.voltage_v - 1.0);
  test::RecordFigure("solves", result.solves);
  test::RecordFigure("newton_iterations", result.iterations);

  const BeamModel<2> model = Model(0);
  auto span_the_beam = [&] {
    GapForce<2, CasimirPressure>(model, CasimirPressure{}, {gap, 0.0, l});
  };
  EXPECT_NO_THROW(span_the_beam());
}

INSTANTIATE_TEST_SUITE_P(OneToAThousand, ElementCountTest, ::testing::Values(1, 2, 13, 100, 1000));

// ---------------------------------------------------------------------------------------------
// An axial load of 0.999999 of the buckling load.

class NearBucklingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const BucklingResult buckling = SolveBuckling(BeamModel<2>(Description(0.0)));
    ASSERT_EQ(buckling.status, Status::kOk);
    critical_n_ = buckling.modes.at(0).critical_load_n;
    mode_ = buckling.modes.at(0).shape;
  }

  BeamDescription Description(double compression_n) const {
    BeamDescription beam = MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 1);
    beam.axial_load = -compression_n;
    return beam;
  }

  double critical_n_ = 0.0;
  Eigen::VectorXd mode_;  ///< the buckling mode (reduced, internal units)
};

// A millionth short of the discrete model's own buckling load, its stiffness K_L - mu G_0 is
// definite with a smallest eigenvalue a millionth of its unloaded one, so a tip force excites the
// buckling mode a million times over: d = phi (phi^T f) / ((mu_1 - mu) phi^T G_0 phi) plus what
// the other modes add, of relative order 1e-6 mu_1 / (mu_2 - mu_1). The difference mu_1 - mu is
// known to 1e-6 of itself (the buckling load to 1e-12), and the solve's round-off is that of a
// matrix a million times worse conditioned than K_L (2e-16 x 1e6 x cond K_L ~ 1e-5): 1e-4
// (measured 1.1e-5).
// A millionth past it, the factorisation meets a negative pivot and says so.
TEST_F(NearBucklingTest, AMillionthShortOfBucklingTheTipForceExcitesTheModeAMillionfold) {
  const BeamModel<2> model(Description((1.0 - 1e-6) * critical_n_));
  LoadCase loads;
  loads.points.push_back(
      {test::kReferenceLength, Eigen::Vector3d(0.0, -1e-9, 0.0), Eigen::Vector3d::Zero()});
  const StaticSolution solution = SolveStatic(model, loads);
  ASSERT_EQ(solution.status, Status::kOk);
  ASSERT_TRUE(solution.displacement.allFinite());
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  const double mu_gap = 1e-6 * critical_n_ / model.units().force;
  const Eigen::VectorXd g_phi = model.Geometric(0) * mode_;
  const Eigen::VectorXd expected = mode_ * (mode_.dot(f) / (mu_gap * mode_.dot(g_phi)));
  EXPECT_LT((solution.displacement - expected).norm(), 1e-4 * expected.norm());
  test::RecordFigure("deviation_from_the_mode",
                     (solution.displacement - expected).norm() / expected.norm());

  EXPECT_EQ(SolveStatic(BeamModel<2>(Description((1.0 + 1e-6) * critical_n_)), loads).status,
            Status::kNotPositiveDefinite);
}

// The first frequency a millionth short of buckling: the eigenvalue that reaches zero there,
// w^2 = (mu_1 - mu) phi^T G_0 phi / phi^T M phi to first order in mu_1 - mu (the buckling mode
// is its null vector), M the mass the prestressed model uses (M_0 - N0 G_1). The second order
// and the series' w^4 M_2 term are 1e-6 of it; the modal solve's absolute round-off,
// eps ||K|| ~ 1e-11 against w^2 ~ 1e-5, 1e-6: 1e-4 relative on w (measured 5.8e-6: 71.7 Hz,
// against 68.8 kHz unloaded).
TEST_F(NearBucklingTest, AMillionthShortOfBucklingTheFirstFrequencyFallsToItsFirstOrderValue) {
  const BeamModel<2> model(Description((1.0 - 1e-6) * critical_n_));
  const ModalResult modes = SolveModal(model, ModalOptions{});
  ASSERT_EQ(modes.status, Status::kOk);
  const double mu_gap = 1e-6 * critical_n_ / model.units().force;
  const Eigen::VectorXd g_phi = model.Geometric(0) * mode_;
  const Eigen::VectorXd m_phi = model.Mass(0) * mode_;
  const double omega = std::sqrt(mu_gap * mode_.dot(g_phi) / mode_.dot(m_phi));
  const double expected = omega / (2.0 * kPi * model.units().time);
  EXPECT_NEAR(modes.modes.at(0).frequency_hz, expected, 1e-4 * expected);
  test::RecordFigure("frequency_hz", modes.modes.at(0).frequency_hz);
  test::RecordFigure("relative_error", modes.modes.at(0).frequency_hz / expected - 1.0);
  test::RecordFigure("sweeps", modes.iterations);
}

// ---------------------------------------------------------------------------------------------
// The Cosserat rod: the elastica to PL^2/EI = 20 and the full-circle end moment.

CosseratRod Rod(int elements, RodTheory theory) {
  CosseratOptions options;
  options.theory = theory;
  return CosseratRod(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                   test::Silicon(), test::ReferenceSection(), elements, 0),
                     options);
}

// A dead tip force of 20 EI/L^2 turns the tip by 1.53 rad (88 degrees) and brings it 0.68 L in.
// The rod differs from the elastica by its O(h^2) discretisation (constant up to 0.5: measured
// 1.0e-4 rad and 6.2e-5 L at 50 elements) and by the strains the Kirchhoff factor leaves,
// alpha (EI/EA + EI/kGA) / L^2 (the rod tests' ElasticaTolerance); halving h cuts the error
// four-fold (measured 4.2).
TEST(ElasticaHardCaseTest, TipForceOfTwentyEiOverL2FollowsTheElasticaAtSecondOrder) {
  constexpr double kAlpha = 20.0;
  const double l = test::kReferenceLength;
  const test::ElasticaTip exact = test::Elastica(kAlpha);
  double previous = 0.0;
  for (int n : {50, 100}) {
    const CosseratRod rod = Rod(n, RodTheory::kKirchhoff);
    CosseratStaticSolver solver(rod);
    ASSERT_EQ(solver.Solve(RodLoads::AtEnd(
                  rod.NodeCount(), Eigen::Vector3d(0.0, -kAlpha * test::Eiz() / (l * l), 0.0),
                  Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())),
              Status::kOk);
    const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / l;
    const CosseratElement& e = rod.elements().front();
    const double tolerance =
        0.5 / (n * n) + kAlpha * (1.0 / e.force_stiffness.x() + 1.0 / e.force_stiffness.y());
    EXPECT_NEAR(-tip.x(), exact.shortening, tolerance) << n;
    EXPECT_NEAR(-tip.y(), exact.deflection, tolerance) << n;
    EXPECT_NEAR(rod.TipRotation(solver.state()).z(), -exact.angle, tolerance) << n;
    const double error = std::hypot(-tip.x() - exact.shortening, -tip.y() - exact.deflection);
    if (previous > 0.0) {
      EXPECT_NEAR(std::log2(previous / error), 2.0, 0.3);
    }
    previous = error;
    test::RecordFigure("load_steps_" + std::to_string(n), solver.last_load_steps());
    test::RecordFigure("cuts_" + std::to_string(n), solver.last_stats().cuts);
    test::RecordFigure("newton_iterations_" + std::to_string(n), solver.last_stats().iterations);
  }
}

class FullCircleTest : public ::testing::TestWithParam<int> {};

// The end moment M = 2 pi EI / L rolls the rod into a closed circle: each element turns by
// psi = h M / EI and keeps its length h (no axial force), so the nodes form a regular polygon on
// the circle through the root of radius (h/2) / sin(psi/2), which is EI/M (1 + psi^2/24 + ...).
// They lie on it to the Newton tolerance's 1e-9, and the tip comes back to the root.
TEST_P(FullCircleTest, EndMomentRollsTheRodIntoAClosedCircleOfRadiusEiOverM) {
  const int n = GetParam();
  const double l = test::kReferenceLength;
  const CosseratRod rod = Rod(n, RodTheory::kSimoReissner);
  CosseratStaticSolver solver(rod);
  const double moment = 2.0 * kPi * test::Eiz() / l;
  ASSERT_EQ(
      solver.Solve(RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, moment))),
      Status::kOk);
  const double psi = 2.0 * kPi / n;
  const double radius = 0.5 * l / n / std::sin(0.5 * psi);
  EXPECT_NEAR(radius, test::Eiz() / moment, psi * psi / 20.0 * radius);
  const Eigen::Matrix3Xd x = rod.NodePositions(solver.state());
  ASSERT_TRUE(x.allFinite());
  for (int i = 0; i < rod.NodeCount(); ++i) {
    const double r = (x.col(i) - Eigen::Vector3d(0.0, radius, 0.0)).norm();
    EXPECT_NEAR(r, radius, 1e-9 * radius) << "node " << i;
  }
  EXPECT_LT(x.col(n).norm(), 1e-9 * l);
  EXPECT_NEAR(rod.TipRotation(solver.state()).z(), 2.0 * kPi, 1e-9);
  test::RecordFigure("newton_iterations", solver.last_stats().iterations);
}

INSTANTIATE_TEST_SUITE_P(Meshes, FullCircleTest, ::testing::Values(3, 50, 1000));

// One element cannot hold the full circle: its end rotations coincide, so its geodesic
// interpolation sees no bending, and no equilibrium exists. The solver says so and keeps the
// state it started from.
TEST(FullCircleRefusalTest, OneElementRefusesAndKeepsTheUndeformedState) {
  const CosseratRod rod = Rod(1, RodTheory::kSimoReissner);
  CosseratStaticSolver solver(rod);
  const double moment = 2.0 * kPi * test::Eiz() / test::kReferenceLength;
  EXPECT_EQ(
      solver.Solve(RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d::Zero(),
                                   Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, moment))),
      Status::kNotConverged);
  EXPECT_EQ(solver.state().displacement.norm(), 0.0);
}

}  // namespace
}  // namespace cosmems
