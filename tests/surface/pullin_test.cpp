// Pull-in against independent oracles: the lumped parallel plate in closed form (static pull-in
// at a third of the gap, V = sqrt(8 k g^3 / 27 eps0 A)) for the fold search, and the distributed
// cantilever against a shooting solution of EI w'''' = -eps0 b V^2 / 2 (g + w)^2 written here.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "cosmems/analysis/pullin_analysis.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

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

// A beam pulled by a pressure P / d^n, in units of L and g: w'''' - tau w'' = -beta / (1 + w)^n
// with beta = b P L^4 / (EI g^(n+1)) and tau = N L^2 / EI. Clamped at x = 0 (w = w' = 0); a
// cantilever is free at x = 1 (w'' = w''' = 0), a bridge clamped there too (w = w' = 0) and may
// stretch: tau = tau0 + kappa int w'^2, kappa = EA g^2 / (2 EI). Shooting on (w''(0), w'''(0),
// beta, tau) for a given deflection -s at the control point (the tip, or midspan), by Newton
// with a finite-difference Jacobian and RK4 on 2000 steps (error ~1e-13); the fold is the
// largest beta over s: walk in steps of 0.05 until beta falls, then golden-section search.
class BeamShooting {
 public:
  BeamShooting(bool bridge, int exponent, double tau0 = 0.0, double kappa = 0.0)
      : bridge_(bridge), exponent_(exponent), tau0_(tau0), kappa_(kappa) {}

  std::array<double, 4> Residual(const std::array<double, 4>& u, double s) const {
    std::array<double, 5> y = {0.0, 0.0, u[0], u[1], 0.0};  // w, w', w'', w''', int w'^2
    const double beta = u[2], tau = u[3];
    auto f = [&](const std::array<double, 5>& v) {
      return std::array<double, 5>{
          v[1], v[2], v[3], tau * v[2] - beta / std::pow(1.0 + v[0], exponent_), v[1] * v[1]};
    };
    const int steps = 2000;
    const double h = 1.0 / steps;
    double midspan = 0.0;
    for (int i = 0; i < steps; ++i) {
      if (i == steps / 2) midspan = y[0];
      const auto k1 = f(y);
      std::array<double, 5> t;
      for (int j = 0; j < 5; ++j) t[j] = y[j] + 0.5 * h * k1[j];
      const auto k2 = f(t);
      for (int j = 0; j < 5; ++j) t[j] = y[j] + 0.5 * h * k2[j];
      const auto k3 = f(t);
      for (int j = 0; j < 5; ++j) t[j] = y[j] + h * k3[j];
      const auto k4 = f(t);
      for (int j = 0; j < 5; ++j) y[j] += h / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    if (bridge_) return {y[0], y[1], midspan + s, tau - tau0_ - kappa_ * y[4]};
    return {y[2], y[3], y[0] + s, tau - tau0_};
  }

  // beta at travel s, Newton from the last solution (the linear one to start).
  double Beta(double s) {
    std::array<double, 4> u = u_;
    if (!started_) {
      u = bridge_ ? std::array<double, 4>{-32.0 * s, 192.0 * s, 384.0 * s, tau0_}
                  : std::array<double, 4>{-4.0 * s, 8.0 * s, 8.0 * s, tau0_};
    }
    for (int iteration = 0; iteration < 50; ++iteration) {
      const std::array<double, 4> r = Residual(u, s);
      if (std::abs(r[0]) + std::abs(r[1]) + std::abs(r[2]) + std::abs(r[3]) < 1e-12) break;
      Eigen::Matrix4d jacobian;
      for (int j = 0; j < 4; ++j) {
        std::array<double, 4> v = u;
        const double h = 1e-7 * std::max(1.0, std::abs(u[j]));
        v[j] += h;
        const std::array<double, 4> rv = Residual(v, s);
        for (int i = 0; i < 4; ++i) jacobian(i, j) = (rv[i] - r[i]) / h;
      }
      const Eigen::Vector4d step = jacobian.lu().solve(-Eigen::Vector4d(r[0], r[1], r[2], r[3]));
      for (int j = 0; j < 4; ++j) u[j] += step[j];
    }
    u_ = u;
    started_ = true;
    return u[2];
  }

  // (travel, beta) at the fold.
  std::pair<double, double> Fold() {
    double s = 0.05, last = Beta(s);
    for (double next; (next = Beta(s + 0.05)) > last; s += 0.05) last = next;
    double a = std::max(0.0, s - 0.05), b = s + 0.05;
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = Beta(c), fd = Beta(d);
    while (b - a > 1e-7) {
      if (fc > fd) {
        b = d, d = c, fd = fc, c = b - g * (b - a), fc = Beta(c);
      } else {
        a = c, c = d, fc = fd, d = a + g * (b - a), fd = Beta(d);
      }
    }
    return {0.5 * (a + b), Beta(0.5 * (a + b))};
  }

 private:
  bool bridge_;
  int exponent_;
  double tau0_, kappa_;
  std::array<double, 4> u_{};
  bool started_ = false;
};

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
