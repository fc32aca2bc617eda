// Transient motion of the Cosserat rod: the small-amplitude frequency against the exact root of
// cos x cosh x = -1, energy over a long large-amplitude run, and statuses on failure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/time/cosserat_newmark_integrator.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::kReferenceLength;

// The exact first frequency of the reference cantilever (68.8 kHz), from cos x cosh x = -1.
double ExactFirstFrequency() {
  const RectangularSection s = test::ReferenceSection();
  return test::BendingFrequency(test::FrequencyRoot(1, -1.0), kReferenceLength, test::Eiz(),
                                test::Silicon().density * s.Area());
}

CosseratRod ReferenceCantilever(int elements) {
  return CosseratRod(MakeStructure(StructureKind::kCantilever, kReferenceLength, test::Silicon(),
                                   test::ReferenceSection(), elements, 0));
}

// The static state under a dead tip force of alpha EI/L^2 down.
RodState Deflected(const CosseratRod& rod, double alpha) {
  CosseratStaticSolver solver(rod);
  const Status status = solver.Solve(RodLoads::AtEnd(
      rod.NodeCount(),
      Eigen::Vector3d(0.0, -alpha * test::Eiz() / (kReferenceLength * kReferenceLength), 0.0),
      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()));
  EXPECT_EQ(status, Status::kOk);
  return solver.state();
}

TEST(CosseratDynamicsTest, SmallAmplitudeFrequencyIsTheExactCantileverRoot) {
  const CosseratRod rod = ReferenceCantilever(50);
  const double f1 = ExactFirstFrequency();
  ASSERT_NEAR(f1, 68.8e3, 0.1e3);
  const double dt = 1.0 / (f1 * 200.0);
  CosseratNewmarkIntegrator integrator(rod, GeneralizedAlphaParameters::Newmark(0.25, 0.5), dt);
  const RodLoads none = RodLoads::None(rod.NodeCount());
  ASSERT_EQ(integrator.Initialize(Deflected(rod, 1e-3), none), Status::kOk);
  // Released from the static shape of a tip force: the tip's upward zero crossings, linearly
  // interpolated, over 20 periods.
  EXPECT_EQ(integrator.TipVelocity().norm(), 0.0);
  std::vector<double> crossings;
  double previous = rod.TipDisplacement(integrator.state()).y();
  for (int step = 0; step < 20 * 200 + 100; ++step) {
    ASSERT_EQ(integrator.Step(none), Status::kOk) << "step " << step;
    const double y = rod.TipDisplacement(integrator.state()).y();
    if (previous < 0.0 && y >= 0.0) {
      crossings.push_back(integrator.time() - dt * y / (y - previous));
    }
    previous = y;
  }
  ASSERT_GE(crossings.size(), 20u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  // Lumped mass and the one-point element at 50 elements, O(h^2); the trapezoidal rule's period
  // elongation (omega dt)^2 / 12 = 8e-5; shear and rotary inertia (t/L)^2 terms, ~1e-4.
  EXPECT_NEAR(1.0 / (period * f1), 1.0, 2e-3);
}

// Total energy (kinetic + strain) of a free vibration from a large deflection.
std::vector<double> FreeVibrationEnergy(const CosseratRod& rod, GeneralizedAlphaParameters p,
                                        int periods, int steps_per_period) {
  const double dt = 1.0 / (ExactFirstFrequency() * steps_per_period);
  CosseratNewmarkIntegrator integrator(rod, p, dt);
  const RodLoads none = RodLoads::None(rod.NodeCount());
  EXPECT_EQ(integrator.Initialize(Deflected(rod, 2.0), none), Status::kOk);
  std::vector<double> energy{integrator.KineticEnergy() + integrator.StrainEnergy()};
  for (int step = 0; step < periods * steps_per_period; ++step) {
    const Status status = integrator.Step(none);
    EXPECT_EQ(status, Status::kOk) << "step " << step;
    if (status != Status::kOk) break;
    energy.push_back(integrator.KineticEnergy() + integrator.StrainEnergy());
  }
  return energy;
}

TEST(CosseratDynamicsTest, LargeAmplitudeRunKeepsItsEnergy) {
  const CosseratRod rod = ReferenceCantilever(20);
  // Released from PL^2/EI = 2 (tip turned 0.8 rad), 30 periods at 100 steps per period, with
  // generalised-alpha at rho_inf = 0.9: the stiff modes' energy is damped, the bending keeps its
  // own to second order (measured: 0.2 % lost over the run; the trapezoidal rule instead gains
  // 17 % and cuts most steps, see CosseratNewmarkIntegrator).
  const std::vector<double> energy =
      FreeVibrationEnergy(rod, GeneralizedAlphaParameters::FromSpectralRadius(0.9), 30, 100);
  ASSERT_EQ(energy.size(), 30u * 100u + 1u);
  const auto [low, high] = std::minmax_element(energy.begin(), energy.end());
  EXPECT_LT((*high - *low) / energy.front(), 1e-2);
  EXPECT_LT(energy.back(), energy.front());  // no energy pumped in over the run
}

TEST(CosseratDynamicsTest, NumericalDampingDissipatesEnergy) {
  const CosseratRod rod = ReferenceCantilever(20);
  // gamma = 0.6, beta = (gamma + 1/2)^2 / 4: first-order accurate, dissipative.
  const std::vector<double> energy =
      FreeVibrationEnergy(rod, GeneralizedAlphaParameters::Newmark(0.3025, 0.6), 5, 50);
  EXPECT_LT(energy.back(), 0.9 * energy.front());
}

TEST(CosseratDynamicsTest, FailureIsReportedAndTheStateKept) {
  const CosseratRod rod = ReferenceCantilever(20);
  const RodLoads none = RodLoads::None(rod.NodeCount());
  const RodLoads pull = RodLoads::AtEnd(
      rod.NodeCount(),
      Eigen::Vector3d(0.0, -test::Eiz() / (kReferenceLength * kReferenceLength), 0.0),
      Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  NewtonOptions one_iteration = RodNewtonOptions();
  one_iteration.max_iterations = 1;
  one_iteration.max_cuts = 0;
  {  // One Newton iteration cannot meet a 1e-9 residual: not converged, nothing changed.
    CosseratNewmarkIntegrator integrator(rod, GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                         0.02 / ExactFirstFrequency(), one_iteration);
    ASSERT_EQ(integrator.Initialize(rod.UndeformedState(), none), Status::kOk);
    EXPECT_EQ(integrator.Step(pull), Status::kNotConverged);
    EXPECT_EQ(integrator.state().displacement.norm(), 0.0);
    EXPECT_EQ(integrator.time(), 0.0);
  }
  // Ten periods in one step under 50 EI/L^2: the iterations leave the stable region, even with
  // the step cut in halves down to 2^-8 of it.
  CosseratNewmarkIntegrator integrator(rod, GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                                       10.0 / ExactFirstFrequency());
  ASSERT_EQ(integrator.Initialize(rod.UndeformedState(), none), Status::kOk);
  RodLoads heavy = pull;
  heavy.dead_forces *= 50.0;
  const Status status = integrator.Step(heavy);
  EXPECT_NE(status, Status::kOk);
  EXPECT_EQ(integrator.state().displacement.norm(), 0.0);
  EXPECT_EQ(integrator.time(), 0.0);
  RodLoads broken = pull;
  broken.dead_forces(1, rod.NodeCount() - 1) = std::nan("");
  EXPECT_EQ(integrator.Step(broken), Status::kNonFinite);
  EXPECT_EQ(integrator.state().displacement.norm(), 0.0);
}

TEST(CosseratDynamicsTest, RejectsExplicitMembersAndBadSteps) {
  const CosseratRod rod = ReferenceCantilever(4);
  EXPECT_THROW(
      CosseratNewmarkIntegrator(rod, GeneralizedAlphaParameters::CentralDifference(), 1e-7),
      std::invalid_argument);
  EXPECT_THROW(CosseratNewmarkIntegrator(rod, GeneralizedAlphaParameters::Newmark(0.25, 0.5), -1.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
