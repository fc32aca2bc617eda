#pragma once

#include <Eigen/Core>

namespace cosmems {

/// A hand holding the stylus, modelled as a spring-damper that pulls the tip toward the scripted
/// point while the device pushes on it. The defaults are a light pen grip: soft enough that a wall
/// at the Omni's renderable stiffness (700 N/m) stops the tip visibly short of the script, and
/// underdamped (damping ratio about 0.27 with the default mass) as a relaxed hand is.
struct HandSpring {
  double stiffness_n_per_m = 300.0;
  double damping_ns_per_m = 2.0;  ///< acts on the tip's velocity relative to the script's
  double mass_kg = 0.045;         ///< the Omni's apparent mass at the tip

  /// Throws std::invalid_argument naming the field and its value, including a stiffness the
  /// step of `period_s` cannot integrate stably.
  void Validate(double period_s) const;
};

/// The tip driven by a HandSpring and the device force, one servo period per Step(). The step is
/// semi-implicit Euler (velocity first, then position from the new velocity): symplectic for the
/// spring, so the hand neither gains nor loses energy by itself and any drift in a closed-loop
/// test comes from the rendered force. The hand's damping is taken implicitly, so it is stable
/// for any damping. Allocation-free.
class SpringHand {
 public:
  SpringHand() = default;
  SpringHand(const HandSpring& spring, double period_s) : spring_(spring), period_s_(period_s) {}

  /// Puts the tip at `position`, at rest.
  void Reset(const Eigen::Vector3d& position) {
    position_ = position;
    velocity_.setZero();
  }

  /// Advances one period: the hand pulls toward `target`, which moves at `target_velocity`, and
  /// the device pushes the tip with `force` [N].
  void Step(const Eigen::Vector3d& target, const Eigen::Vector3d& target_velocity,
            const Eigen::Vector3d& force);

  bool finite() const { return position_.allFinite() && velocity_.allFinite(); }
  const Eigen::Vector3d& position() const { return position_; }
  const Eigen::Vector3d& velocity() const { return velocity_; }

 private:
  HandSpring spring_;
  double period_s_ = 1e-3;
  Eigen::Vector3d position_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_ = Eigen::Vector3d::Zero();
};

}  // namespace cosmems
