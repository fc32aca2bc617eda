// Squeeze-film damping against independent oracles: the power the film takes from a beam moving
// in a polynomial shape against its closed-form integral, with and without rarefaction; both
// tangents against central differences of the force; and the free decay of the reference
// cantilever against the mass-proportional Rayleigh damping the film reduces to for small motion,
// run by the linear integrator.
#include "cosmems/surface/squeeze_film.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "cosmems/beam/load_vector.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "force_differences.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::kReferenceGap;
using test::kReferenceLength;
using test::kReferenceThickness;
using test::kReferenceWidth;
constexpr double kAir = 1.81e-5;  // Pa s

BeamModel<2> Cantilever() {
  return BeamModel<2>(MakeStructure(StructureKind::kCantilever, kReferenceLength, test::Silicon(),
                                    test::ReferenceSection(), 20, 0));
}

// The nodal values of v_y = x^2 / L^2 [m/s] (1 m/s at the tip), internal units.
Eigen::VectorXd Parabola(const BeamModel<2>& model) {
  const UnitSystem& u = model.units();
  const double speed = u.length / u.time;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (std::size_t k = 0; k < model.NodeX().size(); ++k) {
    const double x = model.NodeX()[k] * u.length;
    const int node = static_cast<int>(k);
    if (const int r = model.dofs().Reduced(node, NodalDof::kUy); r >= 0) {
      v[r] = x * x / (kReferenceLength * kReferenceLength) / speed;
    }
    if (const int r = model.dofs().Reduced(node, NodalDof::kRz); r >= 0) {
      v[r] = 2 * x / (kReferenceLength * kReferenceLength) / speed *
             u.length;  // d(v_y)/dx in internal units
    }
  }
  return v;
}

// The power v^T r [W] the film takes at the undeformed gap.
double Power(SqueezeFilm<2>& film, const BeamModel<2>& model, const Eigen::VectorXd& v) {
  const int n = model.FreeDofCount();
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
  ForceTangent tangent(n, model.Stiffness().bandwidth());
  tangent.Clear();
  EXPECT_TRUE(film.EvaluateViscous(Eigen::VectorXd::Zero(n), v, 0.0, r, tangent));
  const UnitSystem& u = model.units();
  return v.dot(r) * u.force * u.length / u.time;
}

TEST(SqueezeFilmTest, TheFilmTakesThePowerOfReynoldsLongStrip) {
  const BeamModel<2> model = Cantilever();
  const Eigen::VectorXd v = Parabola(model);
  // int_0^L c (x^2/L^2)^2 dx = c L / 5, c = mu b^3 / g^3: the Hermite cubics hold x^2 and four
  // Gauss points integrate its square exactly, so only round-off remains (1e-12).
  SqueezeFilm<2> film(model, SqueezeFilmOptions{kAir, 0.0}, kReferenceGap);
  const double c = kAir * std::pow(kReferenceWidth / kReferenceGap, 3);
  EXPECT_NEAR(Power(film, model, v), c * kReferenceLength / 5.0, 1e-12 * c * kReferenceLength);
  // Rarefied air (68 nm at 1 atm): mu / (1 + 9.638 Kn^1.159), Kn = 0.034, 0.192 of the damping
  // lost to slip.
  SqueezeFilm<2> rarefied(model, SqueezeFilmOptions{kAir, 68e-9}, kReferenceGap);
  const double slip = 1.0 + 9.638 * std::pow(68e-9 / kReferenceGap, 1.159);
  EXPECT_NEAR(Power(rarefied, model, v), c / slip * kReferenceLength / 5.0,
              1e-12 * c * kReferenceLength);
}

TEST(SqueezeFilmTest, TangentsMatchDifferencesOfTheForce) {
  const BeamModel<2> model = Cantilever();
  const int n = model.FreeDofCount();
  // Bent toward the substrate like a tip load, the tip at 60 % of the gap, moving in a wave.
  LoadCase loads;
  loads.points.push_back({kReferenceLength, Eigen::Vector3d(0, -1.0, 0), Eigen::Vector3d::Zero()});
  Eigen::VectorXd d = model.Stiffness().ToDense().llt().solve(AssembleLoads(model, loads));
  d *= 0.6 * kReferenceGap / model.units().length / -d[model.dofs().Reduced(20, NodalDof::kUy)];
  Eigen::VectorXd v(n);
  for (int i = 0; i < n; ++i) v[i] = 1e-3 * std::sin(0.7 * i + 0.2);
  SqueezeFilm<2> film(model, SqueezeFilmOptions{kAir, 68e-9}, kReferenceGap);
  // Central differences of a smooth force: h = 1e-6 of the displacement's scale keeps the
  // truncation (h^2) and the cancellation (1e-16 / h) near 1e-10.
  test::ExpectViscousTangentsMatchDifferences(film, d, v, model.Stiffness().bandwidth(),
                                              1e-6 * d.cwiseAbs().maxCoeff(), 1e-6, 1e-6);
}

// For small motion the film is c = mu b^3 / g^3 per length, uniform; so is rho A, and the
// consistent matrix of c is (c / rho A) M: mass-proportional Rayleigh damping, which damps every
// mode at zeta = c / (2 rho A w) (0.23 for the first mode: Q = 2.2, as such beams have in air).
TEST(SqueezeFilmTest, SmallMotionDecaysAsTheMassProportionalDampingItReducesTo) {
  const BeamModel<2> model = Cantilever();
  const UnitSystem& u = model.units();
  const int n = model.FreeDofCount();
  const int tip = model.dofs().Reduced(20, NodalDof::kUy);
  LoadCase loads;
  loads.points.push_back({kReferenceLength, Eigen::Vector3d(0, -1.0, 0), Eigen::Vector3d::Zero()});
  Eigen::VectorXd d0 = model.Stiffness().ToDense().llt().solve(AssembleLoads(model, loads));
  d0 *= 1e-5 * kReferenceGap / u.length / -d0[tip];  // the tip 1e-5 of the gap down, let go
  const double c = kAir * std::pow(kReferenceWidth / kReferenceGap, 3);
  const double alpha =
      c / (test::Silicon().density * kReferenceWidth * kReferenceThickness);  // 1/s
  const double period = 14.5e-6, dt = period / 50 / u.time;
  const auto parameters = GeneralizedAlphaParameters::Newmark(0.25, 0.5);
  SqueezeFilm<2> film(model, SqueezeFilmOptions{kAir, 0.0}, kReferenceGap);
  NonlinearNewmarkIntegrator with_film(model.Mass(0), model.Stiffness(), {}, film, parameters, dt);
  LinearNewmarkIntegrator rayleigh(model.Mass(0), model.Stiffness(),
                                   RayleighDamping{alpha * u.time, 0.0}, parameters, dt);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  ASSERT_EQ(with_film.Initialize(d0, zero, zero), Status::kOk);
  ASSERT_EQ(rayleigh.Initialize(d0, zero, zero), Status::kOk);
  double largest = 0.0;
  // Three periods: the amplitude falls as exp(-alpha t / 2), to 1.5 % of the start.
  for (int step = 0; step < 150; ++step) {
    ASSERT_EQ(with_film.Step(zero), Status::kOk);
    ASSERT_EQ(rayleigh.Step(zero), Status::kOk);
    largest =
        std::max(largest, std::abs(with_film.displacement()[tip] - rayleigh.displacement()[tip]));
  }
  // The film's coefficient varies by 3e-5 of itself over the motion, which bounds its effect on
  // the history well below 2e-5 of the start (measured: 3.1e-6).
  EXPECT_LT(largest, 2e-5 * std::abs(d0[tip]));
  EXPECT_LT(std::abs(with_film.displacement()[tip]), 0.02 * std::abs(d0[tip]));  // it damped
}

}  // namespace
}  // namespace cosmems
