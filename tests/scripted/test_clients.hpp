#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "cosmems/haptics/servo_client.hpp"
#include "extreme_values.hpp"

namespace cosmems {

/// A horizontal virtual wall: F = k max(0, y_wall - y) along +y. Deterministic and stateless, so
/// equal states give bit-identical forces.
class WallClient final : public ServoClient {
 public:
  WallClient(double y_wall_m, double stiffness_n_per_m)
      : y_wall_m_(y_wall_m), stiffness_(stiffness_n_per_m) {}

  void Tick(const DeviceState& state, ForceCommand& command) noexcept override {
    const double depth = std::max(0.0, y_wall_m_ - state.position_m.y());
    command.force_n = Eigen::Vector3d(0.0, stiffness_ * depth, 0.0);
  }

 private:
  double y_wall_m_;
  double stiffness_;
};

/// A broken client. It alternates 800 ticks of large forces pointing anywhere (the clamp's and
/// the slew limit's work: a fault restarts the safety layer's 0.5 s ramp-in, so faults must
/// pause long enough for forces to grow) with 200 ticks of a random mix of huge, NaN, infinite,
/// invalid, stale, negative-age and extreme (test::ExtremeValues) forces. Seeded, so a failure
/// reproduces.
class ChaoticClient final : public ServoClient {
 public:
  explicit ChaoticClient(std::uint64_t seed) : random_(seed) {}

  void Tick(const DeviceState&, ForceCommand& command) noexcept override {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Eigen::Vector3d direction(unit(random_), unit(random_), unit(random_));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const bool faulty = ticks_++ % 1000 >= 800;
    switch (faulty ? std::uniform_int_distribution<int>(0, 6)(random_) : 7) {
      case 0:
        command.force_n = 1e300 * direction;
        break;
      case 1:
        command.force_n = Eigen::Vector3d(nan, 1.0, 0.0);
        break;
      case 2:
        command.force_n = Eigen::Vector3d(0.0, -inf, inf);
        break;
      case 3:
        command.force_n = 1e6 * direction;
        command.valid = false;
        break;
      case 4:
        command.force_n = 1e3 * direction;
        command.age_s = 1.0;
        break;
      case 5:
        command.force_n = direction;
        command.age_s = -1.0;
        break;
      case 6:
        command.force_n = direction;
        command.force_n[static_cast<int>(ticks_ % 3)] = extremes_[ticks_ % extremes_.size()];
        break;
      default:
        command.force_n = 5.0 * direction;
        break;
    }
  }

 private:
  std::mt19937_64 random_;
  std::uint64_t ticks_ = 0;
  std::vector<double> extremes_ = test::ExtremeValues();
};

}  // namespace cosmems
