// Hard cases of the touch: a stylus that jumps 10 mm, sends NaN or stalls, driving the paper's
// scene (contact, stiction and the Casimir force) through the whole servo path (ScriptedDevice,
// HapticLoop with the physics in the tick, HapticStructure on the cantilever's netlist,
// SafetyLayer), with the physics in 10
// steps of 100 us a tick or in one step of 1 ms. Every force sent stays finite, within the
// device's limit and its slew limit; every beam state stays finite; a tick whose physics fails
// says so and its force goes to zero along the slew limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cosmems/haptics/built_in_specs.hpp"
#include "cosmems/haptics/haptic_loop.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "haptics/haptic_test_beam.hpp"
#include "haptics/reference_touch.hpp"
#include "hard_cases/hard_case_support.hpp"
#include "scripted/table_trajectory.hpp"

namespace cosmems {
namespace {

constexpr double kRateHz = 1000.0;
constexpr int kTicks = 2001;  // two presses of 1 s

using test::TableTrajectory;

enum class Script { kPress, kJumps, kNaN, kStalls };

// Each second: down 23 mm along a raised cosine over 0.3 s (the probe through its 2 um clearance
// and the 2 um gap, pressing the tip onto the substrate), held 0.3 s, up over 0.3 s, at rest.
// Jumps: every other 50 ms the stylus is 10 mm off along x, y or z in turn. NaN: the first 30 ms
// of every 100 ms report a NaN height. Stalls: the stylus freezes for the second half of every
// 300 ms, then snaps to where the script has got to.
std::vector<Eigen::Vector3d> Points(Script script) {
  std::vector<Eigen::Vector3d> points;
  for (int n = 0; n < kTicks; ++n) {
    const double t = std::fmod(n / kRateHz, 1.0);
    double s = 0.0;
    if (t < 0.3) {
      s = 0.5 * (1.0 - std::cos(kPi * t / 0.3));
    } else if (t < 0.6) {
      s = 1.0;
    } else if (t < 0.9) {
      s = 0.5 * (1.0 + std::cos(kPi * (t - 0.6) / 0.3));
    }
    points.emplace_back(0.0, -0.023 * s, 0.0);
  }
  for (std::size_t n = 0; n < points.size(); ++n) {
    if (script == Script::kJumps && n / 50 % 2 == 1) {
      points[n][static_cast<int>(n / 100 % 3)] += 0.010;
    } else if (script == Script::kNaN && n % 100 < 30) {
      points[n].y() = std::numeric_limits<double>::quiet_NaN();
    } else if (script == Script::kStalls && n % 300 >= 150) {
      points[n] = points[n - n % 300 + 149];
    }
  }
  return points;
}

struct StylusCase {
  Script script;
  int substeps;  ///< physics steps a 1 ms tick
};

// Every tick's physics runs, in every case. After a stall the stylus snaps 12 mm (2.3 um of
// probe) into the beam: Newton's iterates cross the substrate, where the Casimir pressure is not
// defined, and are pulled back along their increment (before that pull-back 348 ticks were
// refused). Newton solves an indefinite step with a raised mass term (before, a tip stuck in
// single 1 ms steps was never peeled off and 1180 of 2001 ticks were refused). In single 1 ms
// steps the jumps' presses failed 5 ticks while the tip came free between them (a jump drove the
// probe 2 um into the free beam at once); held by its tip since the first press, the beam now
// takes every jump.

std::string StylusName(const ::testing::TestParamInfo<StylusCase>& info) {
  const char* names[] = {"Press", "Jumps10mm", "NaN", "Stalls"};
  return std::string(names[static_cast<int>(info.param.script)]) + "_" +
         std::to_string(info.param.substeps) + "Substeps";
}

class StylusTest : public ::testing::TestWithParam<StylusCase> {};

// Rounding allowance for the bounds, as in the scripted safety tests: the layer scales a force
// or a change to exactly its limit, which rounds by a few ulps.
constexpr double kRounding = 1e-12;

TEST_P(StylusTest, EveryForceStaysBoundedAndEveryFailedTickSaysSo) {
  const auto [script, substeps] = GetParam();
  HapticPhysicsOptions physics;
  physics.substeps = substeps;
  test::ReferenceTouch touch(physics);
  HapticStructure& beam = touch.beam;
  HapticLoop& loop = touch.loop;
  ScriptedOptions scripted;
  scripted.clock = ScriptedClock::kManual;
  scripted.specs = touch.specs;
  const std::vector<Eigen::Vector3d> points = Points(script);
  ScriptedDevice device(std::make_unique<TableTrajectory>(points, kRateHz), scripted);
  ASSERT_EQ(device.Open(), DeviceStatus::kOk);
  ASSERT_EQ(device.Start(loop), DeviceStatus::kOk);

  HapticFrame frame = beam.MakeFrame();
  long failed = 0, non_finite_status = 0;
  while (device.Step(1) > 0) {
    beam.Fill(frame);
    ASSERT_TRUE(frame.carrier_motion_m.allFinite()) << "tick " << device.ticks();
    ASSERT_TRUE(frame.probe_force_n.allFinite()) << "tick " << device.ticks();
    if (frame.status != Status::kOk) {
      ++failed;
      non_finite_status += frame.status == Status::kNonFinite;
    }
  }
  device.Stop();
  EXPECT_EQ(static_cast<long>(loop.failed_ticks()), failed);
  EXPECT_EQ(frame.status, Status::kOk);

  const double limit = device.force_limit_n();
  const double slew = SafetyLayer(scripted.safety, device.specs()).slew_per_tick();
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  long breaches = 0;
  for (const ScriptedSample& sample : device.Recorded()) {
    const Eigen::Vector3d& force = sample.force_n;
    breaches += !(force.allFinite() && force.norm() <= limit * (1.0 + kRounding) &&
                  (force - previous).norm() <= slew * (1.0 + kRounding));
    previous = force;
  }
  EXPECT_EQ(breaches, 0);
  const SafetyCounters& counters = device.safety_counters();
  const long nan_ticks = std::count_if(points.begin(), points.end(),
                                       [](const Eigen::Vector3d& p) { return !p.allFinite(); });
  EXPECT_EQ(counters.non_finite_states, nan_ticks);
  // A failed tick leaves the local model invalid, which the safety layer takes as a stale force.
  EXPECT_EQ(counters.stale_forces, failed);
  EXPECT_EQ(failed, 0);
  // The first press sticks the tip, and the stylus cannot pull: when it lifts or jumps off, the
  // 200 um beam, longer than its arc-shaped detachment length (100 um), stays held by its tip
  // (doc/surface.md), through every later press, until a reset.
  EXPECT_EQ(frame.events.stuck, 1);
  EXPECT_EQ(frame.events.releases, 0);
  EXPECT_TRUE(frame.contact.Stuck());
  test::RecordFigure("failed_ticks", failed);
  test::RecordFigure("failed_ticks_non_finite", non_finite_status);
  test::RecordFigure("clamped", counters.clamped);
  test::RecordFigure("slew_limited", counters.slew_limited);
  test::RecordFigure("stuck", frame.events.stuck);
  test::RecordFigure("releases", frame.events.releases);
}

INSTANTIATE_TEST_SUITE_P(
    Scripts, StylusTest,
    ::testing::Values(StylusCase{Script::kPress, 10}, StylusCase{Script::kJumps, 10},
                      StylusCase{Script::kNaN, 10}, StylusCase{Script::kStalls, 10},
                      StylusCase{Script::kPress, 1}, StylusCase{Script::kJumps, 1}),
    StylusName);

// A NaN probe position handed to the physics directly (HapticLoop never hands it one: the device
// shows its client no state it got wrong): the tick is refused as non-finite before the probe
// moves, with the beam kept where it was (the Casimir force alone would have moved it) and the
// local model invalid, and the next tick with a real position runs again.
TEST(NaNProbeTest, ANaNProbeIsRefusedAndTheNextTickRunsAgain) {
  const FrameModel model(test::HapticCantileverNetlist());
  test::HapticNetlistSurface forces(model);
  HapticStructure beam(model, ProbeOptions{test::kProbeRadius, 20.0}, &forces.all, &forces.contact);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(beam.Advance(Eigen::Vector3d(test::kReferenceLength, nan, 0.0), 0.0),
            Status::kNonFinite);
  EXPECT_FALSE(beam.local_model().valid);
  EXPECT_EQ(beam.displacement().norm(), 0.0);
  const Eigen::Vector3d above(test::kReferenceLength, 1e-6 + test::kProbeRadius + 1e-6, 0.0);
  ASSERT_EQ(beam.Advance(above, 1e-3), Status::kOk);
  EXPECT_TRUE(beam.local_model().valid);
  EXPECT_EQ(beam.local_model().force_n, 0.0);
  EXPECT_TRUE(beam.displacement().allFinite());
}

}  // namespace
}  // namespace cosmems
