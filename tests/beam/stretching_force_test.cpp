// Mid-plane stretching against independent oracles: finite differences of its energy for the
// force and of the force for the tangent; the clamped-clamped beam under a uniform load solved
// in closed form for a given tension, with the tension found by bisection in the test; the
// single-mode Duffing estimate of the hardening backbone at small amplitude; the linear beam at
// small loads.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "beam/stretched_bridge.hpp"
#include "force_differences.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::Eiz;
using test::kReferenceLength;
const double kThickness = test::ReferenceSection().thickness;

double Ea() { return test::Silicon().young_modulus * test::ReferenceSection().Area(); }

BeamDescription Bridge(int elements, int order = 1) {
  return MakeStructure(StructureKind::kBridge, kReferenceLength, test::Silicon(),
                       test::ReferenceSection(), elements, order);
}

LoadCase Uniform(double q) {
  LoadCase loads;
  loads.distributed = Eigen::Vector3d(0, q, 0);
  return loads;
}

// Energy of stretching beyond the linear model: s^2 / (2C), s = 1/2 d^T G0 d.
template <int Dim>
double Energy(const BeamModel<Dim>& model, const StretchingForce<Dim>& force,
              const Eigen::VectorXd& d) {
  const double s = 0.5 * d.dot(model.Geometric(0) * d);
  return s * s / (2 * force.Compliance());
}

// Central differences with h = 1e-6 of a unit-sized state: truncation ~1e-12, round-off
// ~1e-10 relative; 1e-7 leaves room for both.
TEST(StretchingForceTest, ForceAndTangentMatchFiniteDifferencesOfTheEnergy) {
  const BeamModel<3> model(Bridge(6));
  StretchingForce<3> force(model);
  std::srand(7);
  const Eigen::VectorXd d = Eigen::VectorXd::Random(model.FreeDofCount());
  test::ExpectForceAndTangentMatchDifferences(
      force, d, model.Stiffness().bandwidth(),
      [&](const Eigen::VectorXd& x) { return Energy(model, force, x); }, 1e-6, 1e-7);
}

TEST(StretchingForceTest, RefusesABeamWithAFreeEnd) {
  const BeamModel<2> cantilever(MakeStructure(StructureKind::kCantilever, kReferenceLength,
                                              test::Silicon(), test::ReferenceSection(), 4, 1));
  EXPECT_THROW(StretchingForce<2>{cantilever}, std::invalid_argument);
}

// The exact bridge of the reference section (tests/beam/stretched_bridge.hpp).
test::StretchedBridge SolveExactBridge(double q, double n0) {
  return test::SolveStretchedBridge(kReferenceLength, Eiz(), Ea(), q, n0);
}

template <int Dim>
NonlinearStaticSolution SolveBridge(const BeamModel<Dim>& model, double q) {
  StretchingForce<Dim> force(model);
  const NonlinearStaticSolution s = SolveNonlinearStatic(model, force, Uniform(q));
  EXPECT_EQ(s.status, Status::kOk);
  return s;
}

// A load that deflects the bridge by five thicknesses, where stretching carries most of it: the
// linear beam would deflect 19 times more. The tension (N L^2 / EI ~ 760) leaves boundary layers
// of width sqrt(EI / N) ~ L / 28 at the clamps that cubics resolve slowly: 40 elements match
// the midspan deflection and the tension within 1e-4 (measured 3.2e-5 and 7.5e-6).
TEST(StretchingForceTest, UniformlyLoadedBridgeMatchesTheExactSolution) {
  const double q = -100.0;  // N/m toward the substrate
  for (double n0 : {0.0, 2e-4}) {
    const test::StretchedBridge exact = SolveExactBridge(q, n0);
    BeamDescription beam = Bridge(40);
    beam.axial_load = n0;
    const BeamModel<2> model(beam);
    const NonlinearStaticSolution s = SolveBridge(model, q);
    const double midspan = BeamField<2>(model, s.displacement).At(kReferenceLength / 2)[1];
    const double tension =
        StretchingForce<2>(model).AxialForce(s.displacement) * model.units().force;
    EXPECT_NEAR(midspan, exact.midspan, 1e-4 * std::abs(exact.midspan)) << n0;
    EXPECT_NEAR(tension, exact.tension, 1e-4 * exact.tension) << n0;
    const double linear = q * std::pow(kReferenceLength, 4) / (384 * Eiz());
    EXPECT_GT(std::abs(linear), 10 * std::abs(midspan));
    EXPECT_GT(std::abs(midspan), 3 * kThickness);
  }
}

// At 1e-4 of a thickness the stretching force is ~1e-8 of the bending force: the nonlinear
// solution equals the linear one to 1e-7.
TEST(StretchingForceTest, SmallLoadsAgreeWithTheLinearBeam) {
  const BeamModel<3> model(Bridge(10));
  const double q = -1e-5;
  const NonlinearStaticSolution s = SolveBridge(model, q);
  const StaticSolution linear = SolveStatic(model, Uniform(q));
  EXPECT_LT((s.displacement - linear.displacement).norm(), 1e-7 * linear.displacement.norm());
}

// Free vibration in the first mode at amplitude a: a single-mode Galerkin model gives the
// Duffing oscillator m x'' + k1 x + k3 x^3 = 0 with k3 = (phi^T G0 phi)^2 / (2C), whose
// frequency rises by 3/8 (k3/k1) a^2 (Lindstedt). Measured over 20 periods with dt = T/400
// against the same integrator at a 1000 times smaller amplitude (which cancels the period error
// of the time step). At a = 0.3 thickness the estimate's own error, O(a^4) and the coupling to
// mode 3, is below 2 % of the shift (measured 0.6 %); asserted at 3 %.
TEST(StretchingForceTest, HardeningBackboneMatchesTheDuffingEstimate) {
  const BeamModel<2> model(Bridge(20, 0));
  StretchingForce<2> force(model);
  ModalOptions one;
  one.count = 1;
  const Eigen::VectorXd phi = SolveModal(model, one).modes.at(0).shape;
  const double g = phi.dot(model.Geometric(0) * phi);
  const double k1 = phi.dot(model.Stiffness() * phi);  // phi^T M phi = 1
  const double k3 = g * g / (2 * force.Compliance());
  const double period = 2 * kPi / std::sqrt(k1);
  const int midspan = model.dofs().Reduced(10, NodalDof::kUy);

  auto measured_frequency = [&](double amplitude) {
    const double scale = amplitude / phi[midspan];
    NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, force,
                                          GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                          period / 400);
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model.FreeDofCount());
    EXPECT_EQ(integrator.Initialize(scale * phi, zero, zero), Status::kOk);
    // Upward zero crossings of the midspan, interpolated linearly within the step.
    std::vector<double> crossings;
    double previous = integrator.displacement()[midspan];
    while (crossings.size() < 21) {
      EXPECT_EQ(integrator.Step(zero), Status::kOk);
      const double now = integrator.displacement()[midspan];
      if (previous < 0 && now >= 0) {
        crossings.push_back(integrator.time() - period / 400 * now / (now - previous));
      }
      previous = now;
    }
    return 20 / (crossings.back() - crossings.front());
  };
  const double a = 0.3 * kThickness / model.units().length;
  const double shift = measured_frequency(a) / measured_frequency(1e-3 * a) - 1;
  const double x = a / phi[midspan];  // the modal amplitude
  const double duffing = 3.0 / 8.0 * k3 / k1 * x * x;
  EXPECT_NEAR(shift, duffing, 0.03 * duffing);
}

// About a deflected state, the tangent's modes must describe small oscillations there: the
// frequency from the modal analysis against the one measured by the nonlinear integrator
// started from the static state plus a small push in mode 1 (1e-4 relative: time step error
// (w dt)^2 / 24 ~ 1e-5 at dt = T/400).
TEST(StretchingForceTest, ModesAboutADeflectedStateMatchSmallOscillationsThere) {
  const BeamModel<2> model(Bridge(20, 0));
  StretchingForce<2> force(model);
  const NonlinearStaticSolution s = SolveBridge(model, -1.0);
  const int n = model.FreeDofCount();
  ModalOptions one;
  one.count = 1;
  const ModalResult about =
      SolveModal(model, ModalPencil::About(model, force, s.displacement), one);
  ASSERT_EQ(about.status, Status::kOk);
  const double straight = SolveModal(model, one).modes.at(0).frequency_hz;
  EXPECT_GT(about.modes[0].frequency_hz, 1.3 * straight);  // strongly stiffened

  const double f_internal = about.modes[0].frequency_hz * model.units().time;
  const double period = 1.0 / f_internal;
  const int midspan = model.dofs().Reduced(10, NodalDof::kUy);
  const Eigen::VectorXd load = AssembleLoads(model, Uniform(-1.0));
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, force,
                                        GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                        period / 400);
  const Eigen::VectorXd push = 1e-4 * s.displacement.norm() * about.modes[0].shape;
  ASSERT_EQ(integrator.Initialize(s.displacement + push, Eigen::VectorXd::Zero(n), load),
            Status::kOk);
  const double rest = s.displacement[midspan];
  std::vector<double> crossings;
  double previous = integrator.displacement()[midspan] - rest;
  while (crossings.size() < 11) {
    ASSERT_EQ(integrator.Step(load), Status::kOk);
    const double now = integrator.displacement()[midspan] - rest;
    if (previous < 0 && now >= 0) {
      crossings.push_back(integrator.time() - period / 400 * now / (now - previous));
    }
    previous = now;
  }
  const double measured = 10 / (crossings.back() - crossings.front());
  EXPECT_NEAR(measured, f_internal, 1e-4 * f_internal);
}

}  // namespace
}  // namespace cosmems
