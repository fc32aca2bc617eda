// Static large deflection of the Cosserat rod against independent oracles: the elastica (by
// shooting), the circle of a pure end moment, linear beam theory at small loads, and exact
// symmetries (objectivity, scale).
#include <gtest/gtest.h>

#include <cmath>

#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "rod/elastica.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::kReferenceLength;

CosseratRod Cantilever(int elements, RodTheory theory = RodTheory::kSimoReissner,
                       double kirchhoff_factor = 1e2) {
  CosseratOptions options;
  options.theory = theory;
  options.kirchhoff_factor = kirchhoff_factor;
  return CosseratRod(MakeStructure(StructureKind::kCantilever, kReferenceLength, test::Silicon(),
                                   test::ReferenceSection(), elements, 0),
                     options);
}

// A dead tip force of alpha EI/L^2 down (-y).
RodLoads DeadTipForce(const CosseratRod& rod, double alpha) {
  return RodLoads::AtEnd(
      rod.NodeCount(),
      Eigen::Vector3d(0.0, -alpha * test::Eiz() / (kReferenceLength * kReferenceLength), 0.0),
      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
}

// The elastica is inextensible and unshearable; the rod differs from it by the discretisation,
// O(h^2) with a constant up to 0.3 (measured at 50 elements, alpha = 10: 4e-5 L in the tip's
// position, 1.3e-4 rad in its angle), and by its axial and shear strains, at most
// alpha (EI/(EA L^2) + EI/(kGA L^2)) of L.
double ElasticaTolerance(const CosseratRod& rod, double alpha) {
  const CosseratElement& e = rod.elements().front();  // internal units: EI_z = L = 1
  const double n = rod.ElementCount();
  return 0.5 / (n * n) + alpha * (1.0 / e.force_stiffness.x() + 1.0 / e.force_stiffness.y());
}

TEST(ElasticaOracleTest, MatchesBisshoppAndDrucker) {
  // Bisshopp & Drucker (1945), Table 1, to the five digits printed.
  constexpr double kPrinted = 1e-5;
  const test::ElasticaTip one = test::Elastica(1.0);
  EXPECT_NEAR(one.deflection, 0.30172, kPrinted);
  EXPECT_NEAR(one.shortening, 0.05643, kPrinted);
  const test::ElasticaTip ten = test::Elastica(10.0);
  EXPECT_NEAR(ten.deflection, 0.81061, kPrinted);
  EXPECT_NEAR(ten.shortening, 0.55500, kPrinted);
}

class DeadTipLoadTest : public ::testing::TestWithParam<RodTheory> {};

TEST_P(DeadTipLoadTest, FollowsTheElasticaUpToPl2OverEiOfTen) {
  const CosseratRod rod = Cantilever(50, GetParam());
  for (double alpha : {0.5, 1.0, 2.0, 5.0, 10.0}) {
    CosseratStaticSolver solver(rod);
    ASSERT_EQ(solver.Solve(DeadTipForce(rod, alpha)), Status::kOk) << "alpha " << alpha;
    const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / kReferenceLength;
    const test::ElasticaTip exact = test::Elastica(alpha);
    const double tolerance = ElasticaTolerance(rod, alpha);
    EXPECT_NEAR(-tip.x(), exact.shortening, tolerance) << "alpha " << alpha;
    EXPECT_NEAR(-tip.y(), exact.deflection, tolerance) << "alpha " << alpha;
    EXPECT_NEAR(tip.z(), 0.0, 1e-12);
    EXPECT_NEAR(rod.TipRotation(solver.state()).z(), -exact.angle, tolerance) << alpha;
  }
}

INSTANTIATE_TEST_SUITE_P(Theories, DeadTipLoadTest,
                         ::testing::Values(RodTheory::kSimoReissner, RodTheory::kKirchhoff));

TEST(CosseratStaticTest, ConvergesToTheElasticaAtSecondOrder) {
  // The Kirchhoff limit takes the strains (1e-6 of L here) out of the comparison.
  constexpr double kAlpha = 5.0;
  const test::ElasticaTip exact = test::Elastica(kAlpha);
  double previous = 0.0;
  for (int elements : {10, 20, 40}) {
    const CosseratRod rod = Cantilever(elements, RodTheory::kKirchhoff);
    CosseratStaticSolver solver(rod);
    ASSERT_EQ(solver.Solve(DeadTipForce(rod, kAlpha)), Status::kOk);
    const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / kReferenceLength;
    const double error = std::hypot(-tip.x() - exact.shortening, -tip.y() - exact.deflection);
    if (previous > 0.0) {
      const double order = std::log2(previous / error);
      EXPECT_GT(order, 1.8) << elements << " elements";
      EXPECT_LT(order, 2.3) << elements << " elements";
    }
    previous = error;
  }
}

TEST(CosseratStaticTest, FollowerForceNormalToTheTipFollowsItsElastica) {
  const CosseratRod rod = Cantilever(50);
  for (double alpha : {1.0, 3.0}) {
    CosseratStaticSolver solver(rod);
    const RodLoads loads = RodLoads::AtEnd(
        rod.NodeCount(), Eigen::Vector3d::Zero(),
        Eigen::Vector3d(0.0, -alpha * test::Eiz() / (kReferenceLength * kReferenceLength), 0.0),
        Eigen::Vector3d::Zero());
    ASSERT_EQ(solver.Solve(loads), Status::kOk) << "alpha " << alpha;
    const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / kReferenceLength;
    const test::ElasticaTip exact = test::FollowerElastica(alpha);
    const double tolerance = ElasticaTolerance(rod, alpha);
    EXPECT_NEAR(-tip.x(), exact.shortening, tolerance) << "alpha " << alpha;
    EXPECT_NEAR(-tip.y(), exact.deflection, tolerance) << "alpha " << alpha;
    EXPECT_NEAR(rod.TipRotation(solver.state()).z(), -exact.angle, tolerance) << alpha;
  }
}

TEST(CosseratStaticTest, EndMomentRollsTheRodIntoACircleOfRadiusEiOverM) {
  const CosseratRod rod = Cantilever(50);
  // The nodes of the discrete solution sit on a circle tangent to the x axis at the root, of
  // radius (h/2)/sin(psi/2) with psi = h M / EI: above EI/M by psi^2/24 (6.6e-4 at the full
  // circle with 50 elements), so their distance from (0, EI/M) is off by up to twice that.
  constexpr double kChord = 1.5e-3;
  for (double turn : {0.25, 0.5, 1.0}) {
    const double angle = 2.0 * kPi * turn;  // M L / EI
    const double moment = angle * test::Eiz() / kReferenceLength;
    CosseratStaticSolver solver(rod);
    ASSERT_EQ(
        solver.Solve(RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, moment))),
        Status::kOk)
        << "turn " << turn;
    const double radius = test::Eiz() / moment;
    const Eigen::Matrix3Xd x = rod.NodePositions(solver.state());
    for (int i = 0; i < rod.NodeCount(); ++i) {
      const Eigen::Vector3d from_centre = x.col(i) - Eigen::Vector3d(0.0, radius, 0.0);
      EXPECT_NEAR(from_centre.norm() / radius, 1.0, kChord) << "node " << i;
      EXPECT_NEAR(x(2, i), 0.0, 1e-12 * kReferenceLength);
    }
    // The curvature psi/h is exact, so the rotation is M L / EI to round-off.
    EXPECT_NEAR(rod.TipRotation(solver.state()).z(), angle, 1e-9);
    EXPECT_NEAR(rod.AxialForce(solver.state()), 0.0, 1e-9 * moment / kReferenceLength);
  }
  // The full circle closes: the tip comes back to the root (a closed regular polygon).
  CosseratStaticSolver solver(rod);
  ASSERT_EQ(solver.Solve(RodLoads::AtEnd(
                rod.NodeCount(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                Eigen::Vector3d(0.0, 0.0, 2.0 * kPi * test::Eiz() / kReferenceLength))),
            Status::kOk);
  const Eigen::Matrix3Xd x = rod.NodePositions(solver.state());
  EXPECT_LT(x.col(rod.NodeCount() - 1).norm(), 1e-9 * kReferenceLength);
}

TEST(CosseratStaticTest, SmallLoadsAgreeWithLinearBeamTheory) {
  const CosseratRod rod = Cantilever(50);
  const CosseratElement& e = rod.elements().front();  // internal units
  // The one-point element's discretisation error in bending, O(h^2), and the load's own
  // nonlinearity, O(alpha^2) = 1e-8.
  constexpr double kLinear = 1e-3;
  constexpr double kAlpha = 1e-4;
  {  // Tip force: P L^3 / 3EI + P L / kGA (Timoshenko).
    CosseratStaticSolver solver(rod);
    ASSERT_EQ(solver.Solve(DeadTipForce(rod, kAlpha)), Status::kOk);
    const double expected = kAlpha / 3.0 + kAlpha / e.force_stiffness.y();
    EXPECT_NEAR(-rod.TipDisplacement(solver.state()).y() / kReferenceLength, expected,
                kLinear * expected);
    EXPECT_NEAR(-rod.TipRotation(solver.state()).z(), kAlpha / 2.0, kLinear * kAlpha / 2.0);
  }
  {  // Tip moment: rotation M L / EI, deflection M L^2 / 2EI.
    CosseratStaticSolver solver(rod);
    const double moment = kAlpha * test::Eiz() / kReferenceLength;
    ASSERT_EQ(
        solver.Solve(RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d::Zero(),
                                     Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, moment))),
        Status::kOk);
    EXPECT_NEAR(rod.TipRotation(solver.state()).z(), kAlpha, 1e-12);
    EXPECT_NEAR(rod.TipDisplacement(solver.state()).y() / kReferenceLength, kAlpha / 2.0,
                kLinear * kAlpha);
  }
  {  // Axial tip force: N = P everywhere, elongation P L / EA.
    CosseratStaticSolver solver(rod);
    const double force = 1e-3 * test::Eiz() / (kReferenceLength * kReferenceLength);
    ASSERT_EQ(solver.Solve(RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d(force, 0.0, 0.0),
                                           Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())),
              Status::kOk);
    EXPECT_NEAR(rod.AxialForce(solver.state()), force, 1e-9 * force);
    EXPECT_NEAR(rod.TipDisplacement(solver.state()).x() / kReferenceLength,
                1e-3 / e.force_stiffness.x(), 1e-9 * 1e-3 / e.force_stiffness.x());
  }
}

TEST(CosseratStaticTest, SmallMidspanLoadOnABridgeAgreesWithLinearTheory) {
  const CosseratRod rod(MakeStructure(StructureKind::kBridge, kReferenceLength, test::Silicon(),
                                      test::ReferenceSection(), 50, 0));
  const CosseratElement& e = rod.elements().front();
  constexpr double kAlpha = 1e-3;
  RodLoads loads = RodLoads::None(rod.NodeCount());
  loads.dead_forces.col(25) =
      Eigen::Vector3d(0.0, -kAlpha * test::Eiz() / (kReferenceLength * kReferenceLength), 0.0);
  CosseratStaticSolver solver(rod);
  ASSERT_EQ(solver.Solve(loads), Status::kOk);
  // P L^3 / 192 EI + P L / 4kGA. The one-point element's O(h^2) bending error is 1.6e-3 of it
  // at 50 elements (its constant is larger clamped-clamped than for the cantilever); the load's
  // stretching nonlinearity, (alpha/192)^2 EA relative to alpha, is 3e-6.
  const double expected = kAlpha / 192.0 + kAlpha / (4.0 * e.force_stiffness.y());
  const Eigen::Vector3d mid =
      rod.DisplacementAt(solver.state(), 0.5 * kReferenceLength) / kReferenceLength;
  EXPECT_NEAR(-mid.y(), expected, 3e-3 * expected);
}

TEST(CosseratStaticTest, ResidualTensionStaysInABridgeAndStiffensIt) {
  constexpr double kX = 2.0;  // x = (L/4) sqrt(T/EI): a tension that halves the deflection
  const double tension = 16.0 * kX * kX * test::Eiz() / (kReferenceLength * kReferenceLength);
  BeamDescription bridge = MakeStructure(StructureKind::kBridge, kReferenceLength, test::Silicon(),
                                         test::ReferenceSection(), 50, 0);
  bridge.axial_load = tension;
  const CosseratRod rod(bridge);
  CosseratStaticSolver solver(rod);
  // Unloaded, the clamps hold the straight rod and its residual tension.
  ASSERT_EQ(solver.Solve(RodLoads::None(rod.NodeCount())), Status::kOk);
  EXPECT_NEAR(rod.AxialForce(solver.state()), tension, 1e-12 * tension);
  // A small midspan load P. On each half, EI w'''' = T w'' with w = w' = 0 at the clamp, w' = 0
  // at midspan and the shear P/2 give w' = P/(2T) (1 - cosh kx + tanh(kReferenceLength/4) sinh kx),
  // k^2 = T/EI, whose integral is delta = (P L / 4T) (1 - tanh(x)/x); shear adds P L / 4kGA.
  constexpr double kAlpha = 1e-3;
  RodLoads loads = RodLoads::None(rod.NodeCount());
  loads.dead_forces.col(25) =
      Eigen::Vector3d(0.0, -kAlpha * test::Eiz() / (kReferenceLength * kReferenceLength), 0.0);
  ASSERT_EQ(solver.Solve(loads), Status::kOk);
  const double t = tension * kReferenceLength * kReferenceLength / test::Eiz();  // internal units
  const double expected = kAlpha / (4.0 * t) * (1.0 - std::tanh(kX) / kX) +
                          kAlpha / (4.0 * rod.elements().front().force_stiffness.y());
  // The one-point element's O(h^2) error, larger with the tension (measured 2.5e-3 at 50
  // elements, 1.6e-3 without it).
  EXPECT_NEAR(-rod.DisplacementAt(solver.state(), 0.5 * kReferenceLength).y() / kReferenceLength,
              expected, 4e-3 * expected);

  // A cantilever cannot hold it: the free end pulls in by N0 L / EA and the force is gone.
  BeamDescription cantilever = MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                             test::Silicon(), test::ReferenceSection(), 20, 0);
  cantilever.axial_load = tension;
  const CosseratRod relaxed(cantilever);
  CosseratStaticSolver relaxing(relaxed);
  ASSERT_EQ(relaxing.Solve(RodLoads::None(relaxed.NodeCount())), Status::kOk);
  const double ea = relaxed.elements().front().force_stiffness.x();  // internal units
  EXPECT_NEAR(relaxed.TipDisplacement(relaxing.state()).x() / kReferenceLength, -t / ea,
              1e-9 * t / ea);
  EXPECT_NEAR(relaxed.AxialForce(relaxing.state()), 0.0, 1e-9 * tension);
}

TEST(CosseratStaticTest, LargeRotationsInThreeDimensionsConvergeAndStayUnit) {
  const CosseratRod rod = Cantilever(50);
  const double gj = test::Silicon().ShearModulus() * test::ReferenceSection().TorsionConstant();
  // Rolled three quarters of a turn about z, twisted by a moment about x and pushed out of
  // plane by a force along z, which the curl turns into torsion and bending about y: the tip
  // frame turns past pi about an axis that is none of the coordinate axes.
  const Eigen::Vector3d moment(0.5 * gj / kReferenceLength, 0.0,
                               1.5 * kPi * test::Eiz() / kReferenceLength);
  const Eigen::Vector3d force(0.0, 0.0, 2.0 * test::Eiz() / (kReferenceLength * kReferenceLength));
  CosseratStaticSolver solver(rod);
  ASSERT_EQ(solver.Solve(RodLoads::AtEnd(rod.NodeCount(), force, Eigen::Vector3d::Zero(), moment)),
            Status::kOk);
  const RodState& s = solver.state();
  EXPECT_TRUE(s.displacement.allFinite());
  for (int i = 0; i < rod.NodeCount(); ++i) {
    EXPECT_NEAR(s.rotation.col(i).norm(), 1.0, 1e-14) << "node " << i;
  }
  const Eigen::Vector3d tip_rotation = rod.TipRotation(s);
  EXPECT_GT(tip_rotation.norm(), kPi);
  EXPECT_GT(std::abs(tip_rotation.x()) + std::abs(tip_rotation.y()), 0.1);
  EXPECT_GT(rod.TipDisplacement(s).z(), 0.1 * kReferenceLength);

  // The same problem turned a quarter turn about x, with width and thickness exchanged, is the
  // same solution turned: frames, loads and supports are all consistent in 3-D.
  const Eigen::Matrix3d q = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix();
  BeamDescription turned = rod.description();
  for (ElementSpec& spec : turned.elements) std::swap(spec.section.width, spec.section.thickness);
  const CosseratRod turned_rod(turned);
  CosseratStaticSolver turned_solver(turned_rod);
  ASSERT_EQ(turned_solver.Solve(RodLoads::AtEnd(turned_rod.NodeCount(), q * force,
                                                Eigen::Vector3d::Zero(), q * moment)),
            Status::kOk);
  const Eigen::Matrix3Xd expected = q * rod.NodePositions(s);
  EXPECT_LT((turned_rod.NodePositions(turned_solver.state()) - expected).norm(),
            1e-8 * kReferenceLength * std::sqrt(rod.NodeCount()));
}

TEST(CosseratStaticTest, PureTwistPastPiIsExact) {
  const CosseratRod rod = Cantilever(20);
  const double gj = test::Silicon().ShearModulus() * test::ReferenceSection().TorsionConstant();
  constexpr double kTwist = 3.0 * kPi;
  CosseratStaticSolver solver(rod);
  ASSERT_EQ(solver.Solve(
                RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                Eigen::Vector3d(kTwist * gj / kReferenceLength, 0.0, 0.0))),
            Status::kOk);
  // Uniform twist kappa_1 = M/GJ, reproduced exactly by the geodesic interpolation.
  EXPECT_LT((rod.TipRotation(solver.state()) - Eigen::Vector3d(kTwist, 0.0, 0.0)).norm(), 1e-9);
  EXPECT_LT(solver.state().displacement.norm(), 1e-12);
}

TEST(CosseratStaticTest, SameRelativeAnswerFromNanometresToMillimetres) {
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();
  int iterations = 0;
  for (double scale : {1e-3, 1.0, 10.0}) {  // L = 200 nm, 200 um, 2 mm
    RectangularSection section = test::ReferenceSection();
    section.width *= scale;
    section.thickness *= scale;
    const CosseratRod rod(MakeStructure(StructureKind::kCantilever, kReferenceLength * scale,
                                        test::Silicon(), section, 20, 0));
    const double ei = test::Silicon().young_modulus * section.SecondMomentZ();
    const double l = kReferenceLength * scale;
    CosseratStaticSolver solver(rod);
    ASSERT_EQ(solver.Solve(RodLoads::AtEnd(rod.NodeCount(),
                                           Eigen::Vector3d(0.0, -3.0 * ei / (l * l), 0.0),
                                           Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero())),
              Status::kOk);
    const Eigen::Vector3d tip = rod.TipDisplacement(solver.state()) / l;
    if (scale == 1e-3) {
      reference = tip;
      iterations = solver.last_stats().iterations;
    } else {
      EXPECT_LT((tip - reference).norm(), 1e-10) << "scale " << scale;
      EXPECT_EQ(solver.last_stats().iterations, iterations) << "scale " << scale;
    }
  }
}

TEST(CosseratStaticTest, WarmStartResolvesASmallLoadChangeInAFewIterations) {
  const CosseratRod rod = Cantilever(50);
  CosseratStaticSolver warm(rod);
  ASSERT_EQ(warm.Solve(DeadTipForce(rod, 2.0)), Status::kOk);
  ASSERT_EQ(warm.Solve(DeadTipForce(rod, 2.02)), Status::kOk);
  EXPECT_EQ(warm.last_load_steps(), 1);
  EXPECT_LE(warm.last_stats().iterations, 3);
  CosseratStaticSolver cold(rod);
  ASSERT_EQ(cold.Solve(DeadTipForce(rod, 2.02)), Status::kOk);
  // Both converged to 1e-9 of the load: the same state to about that relative size.
  EXPECT_LT((warm.state().displacement - cold.state().displacement).norm(), 1e-8);
  // Unchanged loads cost no iteration.
  ASSERT_EQ(warm.Solve(DeadTipForce(rod, 2.02)), Status::kOk);
  EXPECT_EQ(warm.last_stats().iterations, 0);
}

TEST(CosseratStaticTest, KirchhoffLimitErrorFallsAsOneOverTheFactor) {
  constexpr double kAlpha = 5.0;
  auto tip = [&](double factor) {
    const CosseratRod rod = Cantilever(20, RodTheory::kKirchhoff, factor);
    CosseratStaticSolver solver(rod);
    EXPECT_EQ(solver.Solve(DeadTipForce(rod, kAlpha)), Status::kOk) << factor;
    return Eigen::Vector3d(rod.TipDisplacement(solver.state()) / kReferenceLength);
  };
  const Eigen::Vector3d x10 = tip(10.0);
  const Eigen::Vector3d x100 = tip(100.0);
  const Eigen::Vector3d x1000 = tip(1000.0);
  // x(f) = x_inf + c / f + O(1/f^2): Richardson's extrapolation from f = 100 and 1000.
  const Eigen::Vector3d limit = (10.0 * x1000 - x100) / 9.0;
  const double error100 = (x100 - limit).norm();
  const double ratio = (x10 - limit).norm() / error100;
  EXPECT_GT(ratio, 8.0);
  EXPECT_LT(ratio, 12.0);
  // Bounded by the strains the factor leaves: alpha (EI/(f EA L^2) + EI/(f kGA L^2)) of L.
  const CosseratRod rod = Cantilever(20, RodTheory::kKirchhoff, 100.0);
  const CosseratElement& e = rod.elements().front();
  EXPECT_LT(error100, kAlpha * (1.0 / e.force_stiffness.x() + 1.0 / e.force_stiffness.y()));
}

TEST(CosseratStaticTest, FailuresAreReportedAndTheStateKept) {
  BeamDescription free_rod = MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                           test::Silicon(), test::ReferenceSection(), 10, 0);
  free_rod.supports.front() = Support::kFree;
  const CosseratRod unsupported(free_rod);
  CosseratStaticSolver solver(unsupported);
  EXPECT_EQ(solver.Solve(DeadTipForce(unsupported, 1.0)), Status::kNotPositiveDefinite);
  EXPECT_EQ(solver.state().displacement.norm(), 0.0);

  const CosseratRod rod = Cantilever(10);
  CosseratStaticSolver good(rod);
  ASSERT_EQ(good.Solve(DeadTipForce(rod, 1.0)), Status::kOk);
  const RodState before = good.state();
  EXPECT_EQ(good.Solve(DeadTipForce(rod, std::nan(""))), Status::kNonFinite);
  EXPECT_EQ((good.state().displacement - before.displacement).norm(), 0.0);
  // The solver still works from where it was.
  EXPECT_EQ(good.Solve(DeadTipForce(rod, 1.5)), Status::kOk);
}

}  // namespace
}  // namespace cosmems
