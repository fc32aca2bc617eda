#pragma once

#include <cstddef>
#include <vector>

namespace cosmems {

/// The multipliers a contact's time step starts from (NonlinearForce::StartStep): the reactions
/// of the state the last Commit() accepted, one augmented-Lagrangian update between steps. A
/// structure pressed steadily then goes on meeting the penetration tolerance without an update
/// inside its steps, each of which would restart Newton: the folded-flexure resonator pressed
/// onto the substrate at one step a tick (contact, stiction, Casimir) took 44 updates inside
/// steps and 2366 force evaluations over 1000 ticks without it, none and 1589 with it.
///
/// Where the update overshoots, a step that began with it needs an update inside it at a point
/// the update moved: a negative stiffness beyond about half the penalty along some motion (the
/// electrostatic pull at the contact plane tilting the serpentine's plate pulled in at 20 V)
/// turns the update into an oscillation, and 103 of its 1001 haptic ticks failed. The first such
/// step turns the update off until the contact is free again, and the multipliers move only
/// where the tolerance is exceeded, as before. Allocates nothing after construction.
class StepStartMultipliers {
 public:
  explicit StepStartMultipliers(std::size_t points) : start_(points, 0.0) {}

  /// Commit(): point k's reaction at the accepted state (its multiplier where it holds none).
  void Record(std::size_t k, double reaction) { start_[k] = reaction; }
  /// Commit() has recorded every point; `free`: the contact is free, which turns the update on.
  void Recorded(bool free) {
    ready_ = true;
    moved_ = false;
    on_ = on_ || free;
  }
  /// Nothing to take: every reaction is zero as every multiplier is, or the state was set by
  /// hand (Reset, StickAll).
  void Forget() {
    ready_ = false;
    moved_ = false;
  }

  /// StartStep(): `lambda` (the committed multipliers) takes the recorded reactions while the
  /// update is on. True when the step's start moved any (again, after a Revert()).
  bool Apply(std::vector<double>& lambda) {
    if (!ready_ || !on_) return false;
    for (std::size_t k = 0; k < lambda.size(); ++k) {
      moved_ = moved_ || lambda[k] != start_[k];
      lambda[k] = start_[k];
    }
    return moved_;
  }
  /// Settle() updated point k's multiplier inside the step; `committed` is its multiplier at the
  /// last Commit(). An update at a point the step's start moved turns the update off.
  void UpdatedInside(std::size_t k, double committed) {
    if (moved_ && start_[k] != committed) on_ = false;
  }

 private:
  std::vector<double> start_;
  bool ready_ = false;  ///< start_ holds the reactions of the last Commit()
  bool on_ = true;      ///< the update between steps is on
  bool moved_ = false;  ///< the start of the step since the last Commit() moved a multiplier
};

}  // namespace cosmems
