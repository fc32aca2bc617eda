// The safety layer holds its three bounds (limit, finiteness, slew) whatever comes in, ramps in,
// zeroes stale and faulty forces, and its passivity controller takes back energy an active
// virtual world makes.
#include "cosmems/haptics/safety_layer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "cosmems/haptics/built_in_specs.hpp"
#include "extreme_values.hpp"

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

// An active world for 2 s: a force along the velocity (-4 N s/m, negative damping) puts energy
// into a hand moving at up to 0.05 m/s. Returns the energy the layer let out to the hand [J].
double EnergyFromAnActiveWorld(SafetyLayer& layer) {
  double energy_to_hand = 0.0;
  for (int tick = 0; tick < 2000; ++tick) {
    DeviceState state;
    state.velocity_m_s = Eigen::Vector3d(0.0, 0.05 * std::sin(0.01 * tick), 0.0);
    ForceCommand command;
    command.force_n = 4.0 * state.velocity_m_s;
    energy_to_hand += layer.Filter(state, command).dot(state.velocity_m_s) * layer.period();
  }
  return energy_to_hand;
}

// The controller must keep the energy an active world lets out within what it has taken in: it
// stays within one tick's worth of the damper's largest power, max_damping v^2 dt.
TEST(SafetyLayerTest, PassivityControllerTakesBackTheEnergyAnActiveWorldMakes) {
  const DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  SafetyOptions options;
  options.ramp_in_s = 0.0;
  SafetyLayer layer(options, specs);
  const double energy_to_hand = EnergyFromAnActiveWorld(layer);
  EXPECT_GT(layer.counters().passivity_activations, 0);
  EXPECT_LE(energy_to_hand, specs.max_damping_ns_per_m * 0.05 * 0.05 * layer.period());
}

// Minutes of dissipative contact (a 4 N s/m damper under a hand moving at up to 0.05 m/s for
// 120 s banks about 0.6 J) must not pay for a later active world: the credit is bounded by the
// ceiling (the force limit times the workspace's diagonal, 0.88 N x 0.2 m for the Omni), so the
// active world (80 s of it could give 0.4 J unopposed) gives the hand at most that, plus a tick
// of the damper's largest power.
TEST(SafetyLayerTest, BankedEnergyIsBoundedSoALaterActiveWorldIsStillOpposed) {
  const DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  SafetyOptions options;
  options.ramp_in_s = 0.0;
  SafetyLayer layer(options, specs);
  const double ceiling =
      layer.force_limit() * (specs.workspace_max_m - specs.workspace_min_m).norm();
  EXPECT_DOUBLE_EQ(layer.passivity_energy_limit(), ceiling);
  double banked = 0.0;
  for (int tick = 0; tick < 120000; ++tick) {
    DeviceState state;
    state.velocity_m_s = Eigen::Vector3d(0.0, 0.05 * std::sin(0.01 * tick), 0.0);
    ForceCommand command;
    command.force_n = -4.0 * state.velocity_m_s;
    banked -= layer.Filter(state, command).dot(state.velocity_m_s) * layer.period();
  }
  ASSERT_GT(banked, 3.0 * ceiling);  // far more than the ceiling went in
  ASSERT_EQ(layer.counters().passivity_activations, 0);
  double energy_to_hand = 0.0;
  for (int round = 0; round < 40; ++round) energy_to_hand += EnergyFromAnActiveWorld(layer);
  EXPECT_GT(layer.counters().passivity_activations, 0);
  EXPECT_LE(energy_to_hand, ceiling + specs.max_damping_ns_per_m * 0.05 * 0.05 * layer.period());
  // A ceiling set by hand is the one used.
  options.passivity_energy_limit_j = 1e-3;
  EXPECT_EQ(SafetyLayer(options, specs).passivity_energy_limit(), 1e-3);
}

// An uncalibrated device does not know where the hand is: nothing is pushed until it is
// calibrated, and then the force ramps in from zero rather than jumping.
TEST(SafetyLayerTest, NoForceUntilTheDeviceIsCalibratedThenARampIn) {
  SafetyOptions options;
  options.passivity_control = false;
  options.slew_limit_n_per_s = 1e6;
  options.ramp_in_s = 0.1;  // 100 ticks at 1 kHz
  SafetyLayer layer(options, BuiltInSpecs("Touch"));
  DeviceState state;
  state.calibrated = false;
  ForceCommand command;
  command.force_n = Eigen::Vector3d(0.0, 0.5, 0.0);
  for (int tick = 0; tick < 50; ++tick) EXPECT_EQ(layer.Filter(state, command).norm(), 0.0);
  EXPECT_EQ(layer.counters().uncalibrated_ticks, 50);
  EXPECT_EQ(layer.counters().device_faults, 0);
  state.calibrated = true;
  EXPECT_NEAR(layer.Filter(state, command).y(), 0.5 / 100.0, 1e-12);
}

// Every extreme value in every component of position, velocity and force, alone and between
// ordinary ticks, in long random runs: the output stays finite, bounded and slew-limited, the
// last guard never has to step in (the inputs are sanitised before any arithmetic), and the
// layer still renders an ordinary force afterwards (the observer's energy is not poisoned).
TEST(SafetyLayerTest, ExtremeMagnitudesAndDenormalsNeverReachTheOutput) {
  const std::vector<double> extremes = test::ExtremeValues();
  for (const bool passivity : {true, false}) {
    SafetyOptions options;
    options.passivity_control = passivity;
    SafetyLayer layer(options, BuiltInSpecs("PHANTOM Omni"));
    std::mt19937 random(passivity ? 3 : 4);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    std::uniform_int_distribution<std::size_t> pick(0, extremes.size() - 1);
    Eigen::Vector3d previous = Eigen::Vector3d::Zero();
    for (int tick = 0; tick < 200000; ++tick) {
      DeviceState state;
      state.position_m = 0.05 * Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
      state.velocity_m_s = Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
      ForceCommand command;
      command.force_n = 2.0 * Eigen::Vector3d(uniform(random), uniform(random), uniform(random));
      if (tick % 3 == 0) {  // one component of one vector (or of all three) is extreme
        const int component = static_cast<int>(tick / 3 % 3);
        const double x = extremes[pick(random)];
        switch (tick / 9 % 4) {
          case 0:
            state.position_m[component] = x;
            break;
          case 1:
            state.velocity_m_s[component] = x;
            break;
          case 2:
            command.force_n[component] = x;
            break;
          default:
            state.velocity_m_s[component] = x;
            command.force_n[component] = -x;
            break;
        }
      }
      const Eigen::Vector3d out = layer.Filter(state, command);
      ExpectBounds(layer, previous, out);
      if (HasFailure()) return;
      previous = out;
    }
    EXPECT_EQ(layer.counters().output_guards, 0);
    EXPECT_GT(layer.counters().out_of_range_states, 0);
    // Ordinary ticks afterwards: the force comes back to what the client asks.
    DeviceState still;
    ForceCommand press;
    press.force_n = Eigen::Vector3d(0.0, 0.5, 0.0);
    for (int tick = 0; tick < 2000; ++tick) layer.Filter(still, press);
    EXPECT_NEAR(layer.last_output().y(), 0.5, 1e-12);
  }
}

// One 1e300 N command pointing against the motion: the hand never received it (the clamp held
// it to the limit), so the observer must not bank ~1e297 J from it; an active world afterwards
// is still caught within one tick's worth of the damper's power.
TEST(SafetyLayerTest, TheObserverBooksOnlyTheForceDelivered) {
  const DeviceSpecs specs = BuiltInSpecs("PHANTOM Omni");
  SafetyOptions options;
  options.ramp_in_s = 0.0;
  SafetyLayer layer(options, specs);
  DeviceState state;
  state.velocity_m_s = Eigen::Vector3d(0.0, 0.05, 0.0);
  ForceCommand huge;
  huge.force_n = Eigen::Vector3d(0.0, -1e300, 0.0);
  layer.Filter(state, huge);
  const double energy_to_hand = EnergyFromAnActiveWorld(layer);
  EXPECT_GT(layer.counters().passivity_activations, 0);
  // What the first tick really banked: the clamped, slewed force over that tick.
  const double banked = layer.slew_per_tick() * 0.05 * layer.period();
  EXPECT_LE(energy_to_hand, banked + specs.max_damping_ns_per_m * 0.05 * 0.05 * layer.period());
}

// A model that claims to come from the future (negative age: a device clock that started again)
// is as stale as an old one.
TEST(SafetyLayerTest, ANegativeModelAgeIsStale) {
  SafetyOptions options;
  options.ramp_in_s = 0.0;
  SafetyLayer layer(options, BuiltInSpecs("PHANTOM Omni"));
  DeviceState state;
  ForceCommand command;
  command.force_n = Eigen::Vector3d(0.0, 0.05, 0.0);
  command.age_s = -0.5;
  EXPECT_EQ(layer.Filter(state, command).norm(), 0.0);
  EXPECT_EQ(layer.counters().stale_forces, 1);
  command.age_s = 0.0;
  EXPECT_GT(layer.Filter(state, command).norm(), 0.0);
}

// A stop brings the force to zero one slew step a tick, within MaxRampDownTicks() from any
// output, and keeps it there.
TEST(SafetyLayerTest, RampDownReachesZeroAlongTheSlewLimit) {
  SafetyOptions options;
  options.ramp_in_s = 0.0;
  options.passivity_control = false;
  options.force_limit_n = 3.3;
  SafetyLayer layer(options, BuiltInSpecs("PHANTOM Omni"));
  DeviceState state;
  ForceCommand command;
  command.force_n = Eigen::Vector3d(3.0, -1.0, 2.0);
  for (int i = 0; i < 100; ++i) layer.Filter(state, command);
  ASSERT_NEAR(layer.last_output().norm(), 3.3, 1e-12);  // clamped to the limit
  Eigen::Vector3d previous = layer.last_output();
  long ticks = 0;
  bool at_rest = false;
  while (!at_rest && ticks < 1000) {
    at_rest = layer.RampDown();
    ++ticks;
    ExpectBounds(layer, previous, layer.last_output());
    previous = layer.last_output();
  }
  EXPECT_TRUE(at_rest);
  EXPECT_EQ(ticks, static_cast<long>(std::ceil(3.3 / layer.slew_per_tick())));
  EXPECT_LE(ticks, layer.MaxRampDownTicks());
  EXPECT_EQ(layer.counters().ramp_down_ticks, ticks);
  EXPECT_TRUE(layer.RampDown());
  EXPECT_EQ(layer.last_output().norm(), 0.0);
}

// A device reporting an infinite, NaN or absurd force, stiffness or damping is held to the
// built-in table's figures for its model, and says which it replaced.
TEST(SafetyLayerTest, AbsurdDeviceSpecsAreBoundedByTheBuiltInTable) {
  DeviceSpecs reported;
  reported.model = "PHANTOM Omni";
  reported.max_force_n = kInf;
  reported.max_continuous_force_n = 1e6;
  reported.max_stiffness_n_per_m = kNaN;
  reported.max_damping_ns_per_m = 2.0;  // below the table's: kept
  reported.workspace_max_m = Eigen::Vector3d(kInf, 0.1, 0.1);
  CompleteSpecs(reported);
  const DeviceSpecs table = BuiltInSpecs("PHANTOM Omni");
  EXPECT_EQ(reported.max_force_n, table.max_force_n);
  EXPECT_EQ(reported.max_continuous_force_n, table.max_continuous_force_n);
  EXPECT_EQ(reported.max_stiffness_n_per_m, table.max_stiffness_n_per_m);
  EXPECT_EQ(reported.max_damping_ns_per_m, 2.0);
  EXPECT_EQ(reported.workspace_max_m, table.workspace_max_m);
  const std::vector<std::string> expected = {"max_force_n", "max_continuous_force_n",
                                             "max_stiffness_n_per_m", "workspace"};
  EXPECT_EQ(reported.bounded_fields, expected);
  SafetyLayer layer(SafetyOptions{}, reported);
  EXPECT_EQ(layer.force_limit(), table.max_continuous_force_n);
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
  // Each bound: an infinite age limit would render a stalled physics thread's last force for
  // ever; a slew limit of 1e-300 N/s would make a stop's ramp last for ever.
  struct Case {
    const char* field;
    double SafetyOptions::*member;
    double value;
  };
  const Case cases[] = {
      {"max_model_age_s", &SafetyOptions::max_model_age_s, kInf},
      {"max_model_age_s", &SafetyOptions::max_model_age_s, kNaN},
      {"max_model_age_s", &SafetyOptions::max_model_age_s, 0.0},
      {"max_model_age_s", &SafetyOptions::max_model_age_s, 2.0},
      {"slew_limit_n_per_s", &SafetyOptions::slew_limit_n_per_s, 1e-300},
      {"slew_limit_n_per_s", &SafetyOptions::slew_limit_n_per_s, 1e7},
      {"ramp_in_s", &SafetyOptions::ramp_in_s, 1e300},
      {"force_limit_n", &SafetyOptions::force_limit_n, kInf},
      {"passivity_energy_limit_j", &SafetyOptions::passivity_energy_limit_j, -1.0},
      {"passivity_energy_limit_j", &SafetyOptions::passivity_energy_limit_j, kNaN}};
  for (const Case& c : cases) {
    SafetyOptions bad;
    bad.*c.member = c.value;
    try {
      bad.Validate();
      ADD_FAILURE() << c.field << " = " << c.value << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos) << e.what();
    }
  }
  DeviceSpecs fast = BuiltInSpecs("Touch");
  fast.nominal_rate_hz = 1e300;  // a tick of 1e-300 s: no slew step would ever be countable
  EXPECT_THROW(SafetyLayer(SafetyOptions{}, fast), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
