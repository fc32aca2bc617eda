// Pull-in against independent oracles: the lumped parallel plate in closed form (static pull-in
// at a third of the gap, V = sqrt(8 k g^3 / 27 eps0 A)) for the fold search, and the distributed
// cantilever against a shooting solution of EI w'''' = -eps0 b V^2 / 2 (g + w)^2 written here.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <optional>

#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "surface/beam_shooting.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::BeamShooting;

// The parallel plate: spring k, plate area A, gap g; at travel s (of g) the voltage that holds
// it is lambda = V^2 = 2 k g^3 s (1 - s)^2 / (eps0 A), stable while k > eps0 A V^2 / (g (1-s))^3.
struct ParallelPlatePath {
  double k = 1.0, area = 1e-8, gap = 1e-6;
  double Scale() const { return 2.0 * k * gap * gap * gap / (kVacuumPermittivity * area); }
  Status Solve(double s, double& lambda, double& slope) const {
    lambda = Scale() * s * (1.0 - s) * (1.0 - s);
    slope = Scale() * (1.0 - s) * (1.0 - 3.0 * s);
    const double softening = kVacuumPermittivity * area * lambda / std::pow(gap * (1.0 - s), 3);
    return k > softening ? Status::kOk : Status::kNotPositiveDefinite;
  }
  void Accept() const {}
};

TEST(PullInTest, FoldSearchFindsTheParallelPlatePullIn) {
  const ParallelPlatePath plate;
  const FoldPoint fold = FindFold(plate);
  ASSERT_EQ(fold.status, Status::kOk);
  const double exact =
      std::sqrt(8.0 * plate.k * std::pow(plate.gap, 3) / (27.0 * kVacuumPermittivity * plate.area));
  // The quadratic model at a slope of 1e-3 of the initial one: the travel within ~1e-3 / 4 of
  // the gap, the voltage (flat at the fold) to its square, ~1e-7.
  EXPECT_NEAR(std::sqrt(fold.load), exact, 1e-7 * exact);
  EXPECT_NEAR(fold.travel, 1.0 / 3.0, 1e-4);
  EXPECT_LT(fold.last_stable_travel, 1.0 / 3.0);
  EXPECT_LT(fold.solves, 40);
}

TEST(PullInTest, CantileverMatchesTheShootingSolution) {
  const double length = test::kReferenceLength, gap = 2e-6;
  const RectangularSection section = test::ReferenceSection();
  const double ei = test::Silicon().young_modulus * section.SecondMomentZ();
  BeamShooting shooting(false, 2);
  const auto [travel, beta] = shooting.Fold();
  const double exact = std::sqrt(beta * 2.0 * ei * gap * gap * gap /
                                 (kVacuumPermittivity * section.width * std::pow(length, 4)));

  const BeamModel<2> model(
      MakeStructure(StructureKind::kCantilever, length, test::Silicon(), section, 20, 1));
  PullInOptions options;
  options.electrode = {gap, 0.0, length};
  options.control_x = length;
  const PullInResult result = SolvePullIn(model, options);
  ASSERT_EQ(result.status, Status::kOk);
  std::printf(
      "shooting: travel %.6f of the gap, V %.8f V; beam: travel %.6f, V %.8f V, %d solves, "
      "%d iterations\n",
      travel, exact, result.travel_m / gap, result.voltage_v, result.solves, result.iterations);
  // 20 cubic elements on a smooth load, the fold's quadratic model and the gap quadrature each
  // leave below 1e-7 of the voltage (measured 5e-8); the travel sits where the path is flat, to
  // the fold search's 1e-3 slope (measured below 1e-6 of the gap).
  EXPECT_NEAR(result.voltage_v, exact, 1e-6 * exact);
  EXPECT_NEAR(result.travel_m / gap, travel, 1e-4);
  // Osterberg & Senturia's closed form for a wide cantilever without fringing fields,
  // V = sqrt(0.28 E t^3 g^3 / (eps0 L^4)), quoted to two digits: within 0.5 %.
  const double osterberg =
      std::sqrt(0.28 * test::Silicon().young_modulus * std::pow(section.thickness, 3) *
                std::pow(gap, 3) / (kVacuumPermittivity * std::pow(length, 4)));
  EXPECT_NEAR(result.voltage_v, osterberg, 5e-3 * osterberg);
  EXPECT_LT(result.displacement_m, result.travel_m);
}

// A rigid plate of length a on a heave spring k and a tilt spring k_t, pulled by the electrode
// under it. Its heave path is the parallel plate's; tilting by theta changes the energy by
// -eps0 b V^2 a^3 theta^2 / (24 (g - w)^3), so the tilt holds while
// k_t > k a^2 s / (6 (1 - s)): with k_t = k a^2 / 18 it gives way at s = 1/4, before the heave's
// fold at 1/3, while the load still rises: a bifurcation.
struct TiltingPlatePath : ParallelPlatePath {
  double plate = 1e-4;  ///< a [m]
  double tilt = 0.0;    ///< k_t [N m]
  Status Solve(double s, double& lambda, double& slope) const {
    const Status heave = ParallelPlatePath::Solve(s, lambda, slope);
    if (heave != Status::kOk) return heave;
    return tilt > k * plate * plate * s / (6.0 * (1.0 - s)) ? Status::kOk
                                                            : Status::kNotPositiveDefinite;
  }
};

TEST(PullInTest, FoldSearchFindsABifurcationBeforeTheFold) {
  TiltingPlatePath plate;
  plate.tilt = plate.k * plate.plate * plate.plate / 18.0;
  const FoldPoint found = FindFold(plate);
  ASSERT_EQ(found.status, Status::kOk);
  EXPECT_EQ(found.instability, Instability::kBifurcation);
  // Bisected to the travel tolerance (1e-7); the load there is rising with slope 0.375 of the
  // scale, so within 0.375 * 1e-7 of the scale: 1e-6 relative of the load 0.14 covers it.
  EXPECT_NEAR(found.travel, 0.25, FoldOptions{}.travel_tolerance);
  const double exact = plate.Scale() * 0.25 * 0.75 * 0.75;
  EXPECT_NEAR(found.load, exact, 1e-6 * exact);
  EXPECT_LT(found.solves, 60);
  // A stiffer tilt outlasts the fold: the classic pull-in at a third of the gap.
  plate.tilt = plate.k * plate.plate * plate.plate;
  const FoldPoint fold = FindFold(plate);
  ASSERT_EQ(fold.status, Status::kOk);
  EXPECT_EQ(fold.instability, Instability::kLimitPoint);
  EXPECT_NEAR(fold.travel, 1.0 / 3.0, 1e-4);
}

// The reference section over a 2 um gap: EI, b, and the conversion of a shooting beta into the
// scale of a pressure P / d^n of unit coefficient (beta = b P L^4 / (EI g^(n+1))).
struct Reference {
  double length = test::kReferenceLength, gap = 2e-6;
  RectangularSection section = test::ReferenceSection();
  double Ei() const { return test::Silicon().young_modulus * section.SecondMomentZ(); }
  double BetaPerScale(int exponent) const {
    return section.width * std::pow(length, 4) / (Ei() * std::pow(gap, exponent + 1));
  }
  BeamModel<2> Model(StructureKind kind, double axial_load = 0.0) const {
    BeamDescription beam = MakeStructure(kind, length, test::Silicon(), section, 20, 1);
    beam.axial_load = axial_load;
    return BeamModel<2>(beam);
  }
  PullInOptions Options(StructureKind kind) const {
    PullInOptions options;
    options.electrode = {gap, 0.0, length};
    options.control_x = kind == StructureKind::kCantilever ? length : 0.5 * length;
    return options;
  }
};

// A bridge pulls in later than a cantilever and, held axially, stretches as it goes, which
// raises its pull-in voltage; a residual tension raises it further. Both against the shooting
// solution with tau0 = N0 L^2 / EI and kappa = EA g^2 / (2 EI) = 6 g^2 / t^2. 20 elements put
// the voltage within 2.1e-6 (linear), 2.4e-6 (stretching) and 3.5e-6 (with tension) of it; the
// tension's boundary layers at the clamps (width L / sqrt(tau)) converge slowest. Tolerance 1e-5.
// The stretching cases pass the linear pull-in travel (0.397), where the bending stiffness alone
// is no longer definite and only the stretching's rank-one term holds the bridge.
TEST(PullInTest, BridgeWithStretchingAndResidualStressMatchesTheShootingSolution) {
  const Reference ref;
  const double kappa = 6.0 * ref.gap * ref.gap / (ref.section.thickness * ref.section.thickness);
  const double tau0 = 20.0;
  struct Case {
    const char* name;
    double tau0, kappa;
  };
  for (const Case c : {Case{"linear", 0.0, 0.0}, Case{"stretching", 0.0, kappa},
                       Case{"stretching and tension", tau0, kappa}}) {
    BeamShooting shooting(true, 2, c.tau0, c.kappa);
    const auto [travel, beta] = shooting.Fold();
    const double exact = std::sqrt(beta / (0.5 * kVacuumPermittivity * ref.BetaPerScale(2)));
    const BeamModel<2> model =
        ref.Model(StructureKind::kBridge, c.tau0 * ref.Ei() / (ref.length * ref.length));
    StretchingForce<2> stretching(model);
    const PullInResult result = SolvePullIn(model, ref.Options(StructureKind::kBridge),
                                            c.kappa > 0.0 ? &stretching : nullptr);
    std::printf("bridge, %s: shooting travel %.6f V %.8f; beam travel %.6f V %.8f (%d solves)\n",
                c.name, travel, exact, result.travel_m / ref.gap, result.voltage_v, result.solves);
    ASSERT_EQ(result.status, Status::kOk) << c.name;
    EXPECT_NEAR(result.voltage_v, exact, 1e-5 * exact) << c.name;
    EXPECT_NEAR(result.travel_m / ref.gap, travel, 1e-3) << c.name;
  }
}

// Pull-in across gap / thickness from 0.1 to 10 against the shooting solution: the 200 um
// cantilever (linear: its axis slides freely, and the ratio only scales the voltage as g^1.5)
// and the 100 um bridge with mid-plane stretching, kappa = 6 g^2 / t^2 from 0.06 to 600. Past
// g / t ~ 1 the stretching dominates the bridge: its fold moves from 0.40 to 0.65 of the gap and
// the voltage rises 4 decades over the range instead of 1.5, and the tension (tau up to ~2000)
// draws the bending into boundary layers at the clamps, L / sqrt(tau) wide (2 um at g / t = 10).
// 20 elements (the CLI's default, 5 um each) leave the bridge's voltage within 1e-3 there
// (measured 7.8e-4; 2.9e-5 at g / t = 3), 80 within 1e-5 everywhere (the error falls as h^4);
// the cantilever's within 1e-6. The travel sits where the path is flat: within 1e-3 of the gap.
TEST(PullInTest, PullInMatchesTheShootingSolutionAcrossGapToThickness) {
  const RectangularSection section = test::ReferenceSection();
  const double t = section.thickness;
  const double ei = test::Silicon().young_modulus * section.SecondMomentZ();
  struct Case {
    StructureKind kind;
    int elements;
    double tolerance;
  };
  for (const Case c :
       {Case{StructureKind::kCantilever, 20, 1e-6}, Case{StructureKind::kBridge, 20, 1e-3},
        Case{StructureKind::kBridge, 80, 1e-5}}) {
    const bool bridge = c.kind == StructureKind::kBridge;
    const double length = bridge ? 100e-6 : test::kReferenceLength;
    const BeamModel<2> model(
        MakeStructure(c.kind, length, test::Silicon(), section, c.elements, 1));
    for (double ratio : {0.1, 0.3, 1.0, 2.0, 3.0, 5.0, 10.0}) {
      const double gap = ratio * t;
      BeamShooting shooting(bridge, 2, 0.0, bridge ? 6.0 * ratio * ratio : 0.0);
      const auto [travel, beta] = shooting.Fold();
      const double exact = std::sqrt(2.0 * beta * ei * std::pow(gap, 3) /
                                     (kVacuumPermittivity * section.width * std::pow(length, 4)));
      std::optional<StretchingForce<2>> stretching;
      if (bridge) stretching.emplace(model);
      PullInOptions options;
      options.electrode = {gap, 0.0, length};
      options.control_x = bridge ? 0.5 * length : length;
      const PullInResult result = SolvePullIn(model, options, stretching ? &*stretching : nullptr);
      std::printf(
          "%s, %d elements, g/t %4.1f: shooting travel %.6f V %.8g; beam travel %.6f V "
          "%.8g (error %.1e, %d solves)\n",
          bridge ? "bridge" : "cantilever", c.elements, ratio, travel, exact, result.travel_m / gap,
          result.voltage_v, result.voltage_v / exact - 1.0, result.solves);
      ASSERT_EQ(result.status, Status::kOk) << ratio;
      EXPECT_EQ(result.instability, Instability::kLimitPoint) << ratio;
      EXPECT_NEAR(result.voltage_v, exact, c.tolerance * exact) << ratio;
      EXPECT_NEAR(result.travel_m / gap, travel, 1e-3) << ratio;
    }
  }
}

// Without any voltage, surface forces alone collapse a beam whose gap is too small: the largest
// multiple of the Casimir (1/d^4) or van der Waals (1/d^3) pressure it withstands, against the
// shooting solution. Below 1 the beam collapses at that gap.
TEST(PullInTest, CasimirAndVanDerWaalsCollapseMatchTheShootingSolution) {
  const Reference ref;
  for (const StructureKind kind : {StructureKind::kCantilever, StructureKind::kBridge}) {
    const bool bridge = kind == StructureKind::kBridge;
    const BeamModel<2> model = ref.Model(kind);
    {
      BeamShooting shooting(bridge, 4);
      const double exact =
          shooting.Fold().second / (CasimirPressure::Coefficient() * ref.BetaPerScale(4));
      const PullInResult result = SolveFold(model, CasimirPressure{}, ref.Options(kind));
      ASSERT_EQ(result.status, Status::kOk);
      std::printf("Casimir, %s: scale %.8e vs %.8e\n", bridge ? "bridge" : "cantilever",
                  result.scale, exact);
      EXPECT_NEAR(result.scale, exact, 1e-5 * exact);
    }
    {
      const VanDerWaalsPressure unit{6.0 * kPi};  // A_H / (6 pi) = 1
      BeamShooting shooting(bridge, 3);
      const double exact = shooting.Fold().second / ref.BetaPerScale(3);
      const PullInResult result = SolveFold(model, unit, ref.Options(kind));
      ASSERT_EQ(result.status, Status::kOk);
      std::printf("van der Waals, %s: scale %.8e vs %.8e\n", bridge ? "bridge" : "cantilever",
                  result.scale, exact);
      EXPECT_NEAR(result.scale, exact, 1e-5 * exact);
    }
  }
}

}  // namespace
}  // namespace cosmems
