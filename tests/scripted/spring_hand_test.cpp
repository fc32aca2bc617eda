#include "cosmems/scripted/spring_hand.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace cosmems {
namespace {

constexpr double kPeriod = 1e-3;

TEST(SpringHandTest, SettlesWhereTheSpringBalancesTheDeviceForce) {
  const HandSpring spring;
  SpringHand hand(spring, kPeriod);
  const Eigen::Vector3d target(0.01, 0.0, -0.02);
  hand.Reset(target);
  const Eigen::Vector3d force(0.0, 0.3, -0.1);  // the device pushes the tip up and away
  for (int i = 0; i < 20000; ++i) hand.Step(target, Eigen::Vector3d::Zero(), force);
  // k (target - x) + f = 0 at rest. Twenty seconds is 444 decay times of the damped
  // oscillation (zeta omega = b / 2m = 22 1/s), so only rounding is left, ~1e-17 m.
  const Eigen::Vector3d rest = target + force / spring.stiffness_n_per_m;
  EXPECT_LT((hand.position() - rest).norm(), 1e-15);
  EXPECT_LT(hand.velocity().norm(), 1e-12);
}

TEST(SpringHandTest, UndampedOscillationKeepsItsAmplitude) {
  HandSpring spring;
  spring.damping_ns_per_m = 0.0;
  SpringHand hand(spring, kPeriod);
  const double amplitude = 0.005;
  hand.Reset(Eigen::Vector3d(amplitude, 0.0, 0.0));
  double largest = 0.0;
  double smallest_peak = amplitude;
  double before = 0.0;  // |x| two steps back
  double last = amplitude;
  // About 1300 oscillations (omega = 81.6 rad/s).
  for (int i = 0; i < 100000; ++i) {
    hand.Step(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
    const double x = std::abs(hand.position().x());
    largest = std::max(largest, x);
    if (last >= before && last > x) smallest_peak = std::min(smallest_peak, last);
    before = last;
    last = x;
  }
  // Semi-implicit Euler conserves a modified energy, so the amplitude neither grows nor decays:
  // it differs from the true one by (omega h)^2 / 8 = 0.08 %, and sampling every 1 ms catches a
  // peak to within 1 - cos(omega h / 2) = 0.08 %. 1 % covers both; an explicit Euler step would
  // have grown the amplitude by (1 + (omega h)^2)^(N/2), a factor e^330 here.
  EXPECT_LT(largest, amplitude * 1.01);
  EXPECT_GT(smallest_peak, amplitude * 0.99);
}

TEST(SpringHandTest, RejectsAStiffnessTheStepCannotIntegrate) {
  HandSpring spring;
  spring.stiffness_n_per_m = 4.0 * spring.mass_kg / (kPeriod * kPeriod);
  try {
    spring.Validate(kPeriod);
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("spring.stiffness_n_per_m"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("stability"), std::string::npos);
  }
  spring.stiffness_n_per_m *= 0.99;
  EXPECT_NO_THROW(spring.Validate(kPeriod));
}

TEST(SpringHandTest, RejectsNonPhysicalParameters) {
  for (const char* field : {"mass_kg", "damping_ns_per_m", "stiffness_n_per_m"}) {
    HandSpring spring;
    const std::string name = field;
    if (name == "mass_kg") spring.mass_kg = 0.0;
    if (name == "damping_ns_per_m") spring.damping_ns_per_m = -1.0;
    if (name == "stiffness_n_per_m") spring.stiffness_n_per_m = std::nan("");
    try {
      spring.Validate(kPeriod);
      ADD_FAILURE() << field;
    } catch (const std::invalid_argument& error) {
      EXPECT_NE(std::string(error.what()).find(std::string("spring.") + field), std::string::npos)
          << error.what();
    }
  }
}

}  // namespace
}  // namespace cosmems
