// The safety layer holds its three bounds (limit, finiteness, slew) whatever comes in, ramps in,
// zeroes stale and faulty forces, and its passivity controller takes back energy an active
// virtual world makes.
#include "cosmems/haptics/safety_layer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cosmems/haptics/built_in_specs.hpp"

namespace cosmems {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Slew and limit are compared with 1e-12 relative slack: the layer scales vectors to exactly
// these lengths, and a norm recomputed from the scaled components differs by rounding.
void ExpectBounds(const SafetyLayer& layer, const Eigen::Vector3d& previous,
                  const Eigen::Vector3d& out) {
  ASSERT_TRUE(out.allFinite());
  EXPECT_LE(out.norm(), layer.force_limit() * (1 + 1e-12));
  EXPECT_LE((out - previous).norm(), layer.slew_per_tick() * (1 + 1e-12));
}

TEST(SafetyLayerTest, RandomAndAdversarialInputsStayWithinTheBounds) {
  const DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  SafetyLayer layer(SafetyOptions{}, specs);
  EXPECT_DOUBLE_EQ(layer.force_limit(), 0.88);  // the continuous force by default
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double bad[] = {kNaN, kInf, -kInf, 1e300, 0.0};
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (int tick = 0; tick < 20000; ++tick) {
    DeviceState state;
    state.tick = static_cast<std::uint64_t>(tick);
    state.position_m = 0.05 * Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
    state.velocity_m_s = Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
    ForceCommand command;
    command.force_n = 10.0 * Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
    switch (tick % 97) {  // now and then something goes wrong
      case 3:
        state.position_m.x() = kNaN;
        break;
      case 5:
        state.velocity_m_s.y() = kInf;
        break;
      case 7:
        command.force_n.z() = bad[(tick / 97) % 5];
        break;
      case 11:
        command.valid = false;
        break;
      case 13:
        command.age_s = 1.0;
        break;
      case 17:
        state.fault = true;
        break;
      case 19:
        state.position_m.x() += 0.01;
        break;  // a 10 mm jump
      default:
        break;
    }
    const Eigen::Vector3d out = layer.Filter(state, command);
    ExpectBounds(layer, previous, out);
    previous = out;
  }
  const SafetyCounters& c = layer.counters();
  EXPECT_GT(c.clamped, 0);
  EXPECT_GT(c.slew_limited, 0);
  EXPECT_GT(c.non_finite_states, 0);
  EXPECT_GT(c.non_finite_forces, 0);
  EXPECT_GT(c.stale_forces, 0);
  EXPECT_GT(c.device_faults, 0);
  EXPECT_LE(c.max_force_n, layer.force_limit() * (1 + 1e-12));
}

TEST(SafetyLayerTest, RampsInAfterStartAndAfterAFault) {
  DeviceSpecs specs = BuiltInSpecs("Touch");
  SafetyOptions options;
  options.passivity_control = false;
  options.slew_limit_n_per_s = 1e6;  // no slew limit here: the ramp alone shapes the force
  options.ramp_in_s = 0.1;           // 100 ticks at 1 kHz
  SafetyLayer layer(options, specs);
  DeviceState state;
  ForceCommand command;
  command.force_n = Eigen::Vector3d(0.0, 0.5, 0.0);
  double force = 0.0;
  for (int tick = 1; tick <= 100; ++tick) {
    force = layer.Filter(state, command).y();
    EXPECT_NEAR(force, 0.5 * tick / 100.0, 1e-12);  // linear in time from zero
  }
  EXPECT_NEAR(layer.Filter(state, command).y(), 0.5, 1e-15);
  state.fault = true;
  EXPECT_EQ(layer.Filter(state, command).y(), 0.0);
  state.fault = false;
  EXPECT_NEAR(layer.Filter(state, command).y(), 0.5 / 100.0, 1e-12);  // ramps in again
}

TEST(SafetyLayerTest, AFaultBringsTheForceDownAlongTheSlewLimit) {
  SafetyOptions options;
  options.passivity_control = false;
  options.ramp_in_s = 0.0;
  SafetyLayer layer(options, BuiltInSpecs("PHANTOM Omni"));
  DeviceState state;
  ForceCommand command;
  command.force_n = Eigen::Vector3d(0.0, 0.8, 0.0);
  for (int i = 0; i < 20; ++i) layer.Filter(state, command);
  ASSERT_NEAR(layer.last_output().y(), 0.8, 1e-12);
  command.valid = false;  // the physics behind the force failed
  const double first = layer.Filter(state, command).y();
  EXPECT_NEAR(first, 0.8 - layer.slew_per_tick(), 1e-12);
  for (int i = 0; i < 10; ++i) layer.Filter(state, command);
  EXPECT_EQ(layer.last_output().norm(), 0.0);
}

// An active world: a force along the velocity (negative damping) puts energy into the hand. The
// controller must keep the energy it lets out within what it has taken in: it stays within one
// tick's worth of the damper's largest power, max_damping v^2 dt.
TEST(SafetyLayerTest, PassivityControllerTakesBackTheEnergyAnActiveWorldMakes) {
  const DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  SafetyOptions options;
  options.ramp_in_s = 0.0;
  SafetyLayer layer(options, specs);
  const double dt = 1e-3;
  double energy_to_hand = 0.0;
  for (int tick = 0; tick < 2000; ++tick) {
    DeviceState state;
    state.velocity_m_s = Eigen::Vector3d(0.0, 0.05 * std::sin(0.01 * tick), 0.0);
    ForceCommand command;
    command.force_n = 4.0 * state.velocity_m_s;  // -4 N s/m: active
    const Eigen::Vector3d out = layer.Filter(state, command);
    energy_to_hand += out.dot(state.velocity_m_s) * dt;
  }
  EXPECT_GT(layer.counters().passivity_activations, 0);
  EXPECT_LE(energy_to_hand, specs.max_damping_ns_per_m * 0.05 * 0.05 * dt);
}

TEST(SafetyLayerTest, RejectsOptionsOutOfRangeByName) {
  SafetyOptions options;
  options.slew_limit_n_per_s = -1.0;
  try {
    options.Validate();
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("slew_limit_n_per_s"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cosmems
