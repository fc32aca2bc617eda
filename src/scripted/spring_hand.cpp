#include "cosmems/scripted/spring_hand.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace cosmems {
namespace {

void Require(bool ok, const char* field, double value, const std::string& condition) {
  if (ok) return;
  std::ostringstream message;
  message << "spring." << field << " = " << value << " must be " << condition;
  throw std::invalid_argument(message.str());
}

}  // namespace

void HandSpring::Validate(double period_s) const {
  Require(std::isfinite(mass_kg) && mass_kg > 0.0, "mass_kg", mass_kg, "finite and > 0");
  Require(std::isfinite(damping_ns_per_m) && damping_ns_per_m >= 0.0, "damping_ns_per_m",
          damping_ns_per_m, "finite and >= 0");
  Require(std::isfinite(stiffness_n_per_m) && stiffness_n_per_m >= 0.0, "stiffness_n_per_m",
          stiffness_n_per_m, "finite and >= 0");
  // Semi-implicit Euler keeps an undamped spring bounded only while omega h < 2.
  const double limit = 4.0 * mass_kg / (period_s * period_s);
  std::ostringstream bound;
  bound << "below 4 m / h^2 = " << limit << " N/m, the step's stability limit at h = " << period_s
        << " s";
  Require(stiffness_n_per_m < limit, "stiffness_n_per_m", stiffness_n_per_m, bound.str());
}

void SpringHand::Step(const Eigen::Vector3d& target, const Eigen::Vector3d& target_velocity,
                      const Eigen::Vector3d& force) {
  // m (v' - v) / h = k (target - x) + b (target_velocity - v') + force, solved for v'.
  const double h_over_m = period_s_ / spring_.mass_kg;
  const Eigen::Vector3d push = spring_.stiffness_n_per_m * (target - position_) +
                               spring_.damping_ns_per_m * target_velocity + force;
  velocity_ = (velocity_ + h_over_m * push) / (1.0 + h_over_m * spring_.damping_ns_per_m);
  position_ += period_s_ * velocity_;
}

}  // namespace cosmems
