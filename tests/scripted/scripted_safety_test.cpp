// The safety layer's three bounds, checked on what a ScriptedDevice actually sent, under scripts
// that misbehave (NaN positions, 10 mm jumps, stalls, random walks) and clients that return
// huge, NaN, infinite, invalid or stale forces.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cosmems/haptics/safety_layer.hpp"
#include "cosmems/scripted/built_in_trajectory.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "extreme_values.hpp"
#include "table_trajectory.hpp"
#include "test_clients.hpp"

namespace cosmems {
namespace {

constexpr double kRateHz = 1000.0;
constexpr double kDurationS = 2.0;

using test::TableTrajectory;

std::vector<Eigen::Vector3d> PressPoints() {
  const auto press = MakeBuiltInTrajectory("press", MotionShape{});
  std::vector<Eigen::Vector3d> points;
  for (int n = 0; n <= kDurationS * kRateHz; ++n) points.push_back(press->Position(n / kRateHz));
  return points;
}

/// Every 50 ms the tip jumps 10 mm, in turn along x, y and z, and back 50 ms later.
std::vector<Eigen::Vector3d> Jumps() {
  std::vector<Eigen::Vector3d> points = PressPoints();
  for (std::size_t n = 0; n < points.size(); ++n) {
    const std::size_t block = n / 50;
    if (block % 2 == 1) points[n][static_cast<int>(block / 2 % 3)] += 0.010;
  }
  return points;
}

/// 30 ms of NaN (or infinity, in one coordinate or all) every 100 ms.
std::vector<Eigen::Vector3d> Gaps() {
  std::vector<Eigen::Vector3d> points = PressPoints();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t n = 0; n < points.size(); ++n) {
    if (n % 100 >= 30) continue;
    switch (n / 100 % 3) {
      case 0:
        points[n].y() = nan;
        break;
      case 1:
        points[n].setConstant(nan);
        break;
      default:
        points[n].x() = -std::numeric_limits<double>::infinity();
        break;
    }
  }
  return points;
}

/// The tip freezes for 150 ms out of every 300 ms, then snaps to where the script has got to.
std::vector<Eigen::Vector3d> Stalls() {
  std::vector<Eigen::Vector3d> points = PressPoints();
  for (std::size_t n = 0; n < points.size(); ++n) {
    if (n % 300 >= 150) points[n] = points[n - n % 300 + 150 - 1];
  }
  return points;
}

/// A random walk of 0.2 mm steps with random 10 mm jumps, NaN bursts and stalls mixed in.
std::vector<Eigen::Vector3d> RandomMess(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> step(0.0, 2e-4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  Eigen::Vector3d p(0.0, 0.0, 0.0);
  int nan_left = 0;
  int stall_left = 0;
  while (points.size() <= kDurationS * kRateHz) {
    const double u = unit(random);
    if (u < 0.01) {
      p += 0.010 * Eigen::Vector3d(step(random), step(random), step(random)).normalized();
    } else if (u < 0.015) {
      nan_left = 5 + static_cast<int>(25 * unit(random));
    } else if (u < 0.02) {
      stall_left = 20 + static_cast<int>(80 * unit(random));
    }
    if (stall_left > 0) {
      --stall_left;
    } else {
      p += Eigen::Vector3d(step(random), step(random), step(random));
    }
    if (nan_left > 0) {
      --nan_left;
      points.push_back(Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
    } else {
      points.push_back(p);
    }
  }
  return points;
}

/// Every 7th tick one coordinate jumps to an extreme value (test::ExtremeValues: magnitudes from
/// 1e150 to the largest double, and denormals), whose backward difference overflows.
std::vector<Eigen::Vector3d> Extremes() {
  std::vector<Eigen::Vector3d> points = PressPoints();
  const std::vector<double> extremes = test::ExtremeValues();
  for (std::size_t n = 0; n < points.size(); n += 7) {
    points[n][static_cast<int>(n / 7 % 3)] = extremes[n / 7 % extremes.size()];
  }
  return points;
}

struct Script {
  std::string name;
  std::vector<Eigen::Vector3d> points;
};

std::vector<Script> Scripts() {
  return {{"jumps", Jumps()},          {"gaps", Gaps()},
          {"stalls", Stalls()},        {"random 1", RandomMess(1)},
          {"random 2", RandomMess(2)}, {"extremes", Extremes()}};
}

/// The default safety settings, and a looser set: full peak force, ten times the slew rate, no
/// ramp-in, no passivity damping. The bounds must hold for both.
std::vector<SafetyOptions> SafetySettings() {
  SafetyOptions loose;
  loose.force_limit_n = 3.3;
  loose.slew_limit_n_per_s = 1000.0;
  loose.ramp_in_s = 0.0;
  loose.passivity_control = false;
  return {SafetyOptions{}, loose};
}

// Rounding allowance for the bounds: the layer scales a change or a force to exactly its limit,
// and that scaling (a division, a product, a sum) rounds by a few ulps, ~1e-16 relative. 1e-12
// relative is far above that and far below any real breach.
constexpr double kRounding = 1e-12;

/// Runs `script` and checks every recorded force; returns what the safety layer counted, so a
/// test can also check that the misbehaviour it meant to cause reached the layer.
SafetyCounters CheckRun(const Script& script, HandModel hand, const SafetyOptions& safety,
                        ServoClient& client) {
  ScriptedOptions options;
  options.clock = ScriptedClock::kManual;
  options.hand = hand;
  options.safety = safety;
  ScriptedDevice device(std::make_unique<TableTrajectory>(script.points, kRateHz), options);
  EXPECT_EQ(device.Open(), DeviceStatus::kOk);
  EXPECT_EQ(device.Start(client), DeviceStatus::kOk);
  while (device.Step(250) > 0) {
  }
  const double limit = device.force_limit_n();
  const double slew = SafetyLayer(safety, device.specs()).slew_per_tick();
  const auto samples = device.Recorded();
  // The script's ticks, then the ramp that brings the force to zero at its end.
  EXPECT_GE(samples.size(), script.points.size());
  EXPECT_LE(samples.size(), script.points.size() + device.MaxRampDownTicks());
  EXPECT_TRUE(samples.empty() || samples.back().force_n.isZero(0.0));
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();  // the layer starts from zero force
  long breaches = 0;  // counted rather than asserted one by one, to report a few, not 2000
  for (std::size_t n = 0; n < samples.size(); ++n) {
    const Eigen::Vector3d& force = samples[n].force_n;
    const bool ok = force.allFinite() && force.norm() <= limit * (1.0 + kRounding) &&
                    (force - previous).norm() <= slew * (1.0 + kRounding) &&
                    // Wherever the script is finite, so is the tip: the spring hand keeps no NaN.
                    (n >= script.points.size() || !script.points[n].allFinite() ||
                     samples[n].position_m.allFinite());
    if (!ok && ++breaches <= 3) {
      ADD_FAILURE() << "tick " << n << ": force " << force.transpose() << " after "
                    << previous.transpose() << " (limit " << limit << ", slew " << slew
                    << "), position " << samples[n].position_m.transpose();
    }
    previous = force;
  }
  EXPECT_EQ(breaches, 0);
  device.Stop();
  const SafetyCounters counters = device.safety_counters();
  EXPECT_LE(counters.max_force_n, limit * (1.0 + kRounding));
  EXPECT_EQ(counters.output_guards, 0);  // the sanitised inputs never needed the last guard
  if (script.name == "gaps") {
    EXPECT_GT(counters.non_finite_states, 0);
  }
  if (script.name == "extremes" && hand == HandModel::kRigid) {
    EXPECT_GT(counters.out_of_range_states, 0);
  }
  return counters;
}

TEST(ScriptedSafetyTest, ChaoticClientStaysWithinTheBounds) {
  std::uint64_t seed = 11;
  for (const Script& script : Scripts()) {
    for (HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
      for (const SafetyOptions& safety : SafetySettings()) {
        SCOPED_TRACE(script.name + (hand == HandModel::kRigid ? ", rigid" : ", spring") +
                     ", slew " + std::to_string(safety.slew_limit_n_per_s));
        ChaoticClient client(++seed);
        const SafetyCounters counters = CheckRun(script, hand, safety, client);
        EXPECT_GT(counters.non_finite_forces, 0);
        EXPECT_GT(counters.stale_forces, 0);
        EXPECT_GT(counters.slew_limited, 0);
      }
    }
  }
}

// A wall a million times stiffer than renderable: the client's forces are finite but huge and
// jump with every millimetre of the scripts' jumps.
TEST(ScriptedSafetyTest, AbsurdlyStiffWallStaysWithinTheBounds) {
  for (const Script& script : Scripts()) {
    for (HandModel hand : {HandModel::kRigid, HandModel::kSpring}) {
      for (const SafetyOptions& safety : SafetySettings()) {
        SCOPED_TRACE(script.name + (hand == HandModel::kRigid ? ", rigid" : ", spring") +
                     ", slew " + std::to_string(safety.slew_limit_n_per_s));
        WallClient client(0.0, 7e8);
        const SafetyCounters counters = CheckRun(script, hand, safety, client);
        EXPECT_GT(counters.clamped, 0);
        EXPECT_GT(counters.slew_limited, 0);
      }
    }
  }
}

}  // namespace
}  // namespace cosmems
