// Dynamic (step) pull-in of the lumped parallel plate through the nonlinear Newmark integrator:
// a voltage switched on at rest swings the plate past its static equilibrium, and the plate
// snaps once the swing reaches half the gap, where the energy balance
//   k y^2 / 2 = eps0 A V^2 y / (2 g (g - y))
// has no turning point any more: V_dyn^2 = k g^3 / (4 eps0 A) = (27/32) V_PI^2.
#include <gtest/gtest.h>

#include <cmath>

#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"

namespace cosmems {
namespace {

constexpr double kStiffness = 1.0;   // N/m
constexpr double kMass = 1e-10;      // kg
constexpr double kArea = 1e-8;       // m^2
constexpr double kPullInGap = 1e-6;  // m

// The plate's electrostatic force as the one unknown's nonlinear force (toward the substrate,
// x < 0), from the library's pressure.
class PlateForce final : public NonlinearForce {
 public:
  explicit PlateForce(double voltage) : pressure_{voltage, 1.0, false} {}
  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double gap = kPullInGap + d[0];
    if (!(gap > 0.0)) return false;
    force[0] += kArea * pressure_.Value(gap);
    tangent.band().Add(0, 0, kArea * pressure_.Slope(gap));
    return true;
  }

 private:
  ElectrostaticPressure pressure_;
};

double StaticPullIn() {
  return std::sqrt(8.0 * kStiffness * std::pow(kPullInGap, 3) /
                   (27.0 * kVacuumPermittivity * kArea));
}

// Whether the plate, released at rest under `voltage`, stays off the substrate for four periods
// of its free oscillation (the swing comes back within one unless it snaps).
bool Holds(double voltage) {
  SymmetricBandMatrix mass(1, 0), stiffness(1, 0);
  mass.Add(0, 0, kMass);
  stiffness.Add(0, 0, kStiffness);
  PlateForce force(voltage);
  const double period = 2.0 * kPi * std::sqrt(kMass / kStiffness);
  NonlinearNewmarkIntegrator integrator(
      mass, stiffness, {}, force, GeneralizedAlphaParameters::Newmark(0.25, 0.5), period / 4000.0);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(1);
  if (integrator.Initialize(zero, zero, zero) != Status::kOk) return false;
  for (int step = 0; step < 16000; ++step) {
    if (integrator.Step(zero) != Status::kOk) return false;
    if (integrator.displacement()[0] < -0.9 * kPullInGap) return false;
  }
  return true;
}

// Bisection on the outcome of whole runs (each run either snaps or swings back): 14 halvings of
// [0.85, 0.95] V_PI. Average acceleration keeps the energy of the swing to O(dt^2) ~ 1e-6 at
// T/4000, which shifts the threshold by about as much; the bisection's own width is 6e-6 V_PI.
TEST(DynamicPullInTest, StepVoltageSnapsAtTheSquareRootOf27Over32OfStaticPullIn) {
  const double v_pi = StaticPullIn();
  double low = 0.85 * v_pi, high = 0.95 * v_pi;
  ASSERT_TRUE(Holds(low));
  ASSERT_FALSE(Holds(high));
  for (int i = 0; i < 14; ++i) {
    const double mid = 0.5 * (low + high);
    (Holds(mid) ? low : high) = mid;
  }
  const double exact = std::sqrt(27.0 / 32.0) * v_pi;
  EXPECT_NEAR(0.5 * (low + high), exact, 2e-5 * exact);
}

}  // namespace
}  // namespace cosmems
