#include "cosmems/scripted/built_in_trajectory.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "cosmems/core/constants.hpp"

namespace cosmems {
namespace {

MotionShape TestShape() {
  MotionShape shape;
  shape.start_m = Eigen::Vector3d(0.005, 0.02, -0.01);
  shape.depth_m = 0.015;
  shape.sweep_m = 0.03;
  shape.period_s = 1.5;
  shape.cycles = 2;
  return shape;
}

std::string ErrorOf(const std::string& name, const MotionShape& shape) {
  try {
    MakeBuiltInTrajectory(name, shape);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "no error";
}

TEST(BuiltInTrajectoryTest, EveryMotionStartsAndEndsAtRestAtTheStartPoint) {
  const MotionShape shape = TestShape();
  for (const std::string& name : BuiltInTrajectoryNames()) {
    SCOPED_TRACE(name);
    const auto motion = MakeBuiltInTrajectory(name, shape);
    EXPECT_EQ(motion->Duration(), shape.cycles * shape.period_s);
    EXPECT_EQ(motion->Position(-1.0), shape.start_m);
    EXPECT_EQ(motion->Position(0.0), shape.start_m);
    EXPECT_EQ(motion->Position(motion->Duration()), shape.start_m);
    EXPECT_EQ(motion->Position(motion->Duration() + 5.0), shape.start_m);
  }
}

TEST(BuiltInTrajectoryTest, PressHoldsAtDepthEveryCycle) {
  const MotionShape shape = TestShape();
  const auto press = MakeBuiltInTrajectory("press", shape);
  const Eigen::Vector3d bottom = shape.start_m - Eigen::Vector3d(0.0, shape.depth_m, 0.0);
  for (int cycle = 0; cycle < shape.cycles; ++cycle) {
    // The hold spans 40 % to 70 % of the period; points strictly inside it, so rounding of t
    // cannot land them on a neighbouring phase.
    for (double u : {0.42, 0.55, 0.68}) {
      EXPECT_EQ(press->Position((cycle + u) * shape.period_s), bottom) << cycle << " " << u;
    }
    EXPECT_GT(press->Position((cycle + 0.2) * shape.period_s).y(), bottom.y());
    EXPECT_LT(press->Position((cycle + 0.2) * shape.period_s).y(), shape.start_m.y());
  }
}

TEST(BuiltInTrajectoryTest, SweepReachesTheFarEndAtDepth) {
  const MotionShape shape = TestShape();
  const auto sweep = MakeBuiltInTrajectory("sweep", shape);
  const Eigen::Vector3d far_end = shape.start_m + Eigen::Vector3d(shape.sweep_m, -shape.depth_m, 0);
  const Eigen::Vector3d bottom = shape.start_m - Eigen::Vector3d(0.0, shape.depth_m, 0.0);
  // At phase boundaries t / period may round to either side; the raised cosine is flat there, so
  // the position moves by far less than the 1e-15 m allowed.
  EXPECT_LT((sweep->Position(0.5 * shape.period_s) - far_end).norm(), 1e-15);
  EXPECT_LT((sweep->Position(0.2 * shape.period_s) - bottom).norm(), 1e-15);
  EXPECT_LT((sweep->Position(0.8 * shape.period_s) - bottom).norm(), 1e-15);
  // Never leaves [start, start + sweep] along x nor goes below the depth.
  for (double t = 0.0; t < sweep->Duration(); t += 1e-3) {
    const Eigen::Vector3d p = sweep->Position(t);
    EXPECT_GE(p.x(), shape.start_m.x());
    EXPECT_LE(p.x(), shape.start_m.x() + shape.sweep_m);
    EXPECT_GE(p.y(), bottom.y());
  }
}

TEST(BuiltInTrajectoryTest, TapMakesFourTapsToDepthPerPeriod) {
  const MotionShape shape = TestShape();
  const auto tap = MakeBuiltInTrajectory("tap", shape);
  const double half_depth = shape.start_m.y() - 0.5 * shape.depth_m;
  const double dt = 1e-4;
  int descents = 0;
  double deepest = shape.start_m.y();
  bool below = false;
  for (double t = 0.0; t <= tap->Duration(); t += dt) {
    const double y = tap->Position(t).y();
    deepest = std::min(deepest, y);
    if (!below && y < half_depth) ++descents;
    below = y < half_depth;
  }
  EXPECT_EQ(descents, 4 * shape.cycles);
  // A sample lands within dt / 2 of each bottom, where the tip is at rest and accelerates at
  // a = depth (pi / tau)^2 / 2 (tau, a sixteenth of the period, is one half-tap), so it misses
  // the bottom by at most a (dt / 2)^2 / 2; 10 % more for the drift of the summed sample times.
  const double tau = shape.period_s / 16.0;
  const double a = shape.depth_m * (kPi / tau) * (kPi / tau) / 2.0;
  EXPECT_NEAR(deepest, shape.start_m.y() - shape.depth_m, 1.1 * a * dt * dt / 8.0);
  // Each tap's bottom sits at a sixteenth of the period (a quarter of the tap slot).
  EXPECT_EQ(tap->Position(shape.period_s / 16.0).y(), shape.start_m.y() - shape.depth_m);
}

// Every phase is a raised cosine, so the motion is C1 with acceleration at most
// amplitude (pi / tau)^2 / 2 for its shortest phase tau. Then the change between consecutive
// finite-difference velocities, |x(t+2h) - 2x(t+h) + x(t)| / h, is at most a_max h; a velocity
// jump anywhere (a C0 join) would show up as a change of order the peak velocity instead.
TEST(BuiltInTrajectoryTest, FiniteDifferenceVelocityIsContinuous) {
  const MotionShape shape = TestShape();
  struct Case {
    const char* name;
    double shortest_phase;  // fraction of the period
    double amplitude;       // largest travel of one phase [m]
  };
  for (const Case& c : {Case{"press", 0.3, shape.depth_m},
                        Case{"sweep", 0.2, std::max(shape.depth_m, shape.sweep_m)},
                        Case{"tap", 1.0 / 16.0, shape.depth_m}}) {
    SCOPED_TRACE(c.name);
    const auto motion = MakeBuiltInTrajectory(c.name, shape);
    const double tau = c.shortest_phase * shape.period_s;
    const double a_max = c.amplitude * (kPi / tau) * (kPi / tau) / 2.0;
    const double h = 1e-5;
    // Positions of order 0.03 m round to ~3.5e-18 m; three of them in a second difference over
    // h = 1e-5 s give ~1e-12 m/s, hence the absolute allowance.
    const double allowed = a_max * h + 1e-11;
    double largest_change = 0.0;
    Eigen::Vector3d x0 = motion->Position(-h);
    Eigen::Vector3d x1 = motion->Position(0.0);
    for (long k = 1; k * h <= motion->Duration() + h; ++k) {
      const Eigen::Vector3d x2 = motion->Position(static_cast<double>(k) * h);
      largest_change = std::max(largest_change, ((x2 - x1) - (x1 - x0)).norm() / h);
      x0 = x1;
      x1 = x2;
    }
    EXPECT_LE(largest_change, allowed);
    // ... and the bound is not vacuous: the motion does accelerate near it.
    EXPECT_GT(largest_change, 0.1 * a_max * h);
  }
}

TEST(BuiltInTrajectoryTest, UnknownNameListsTheValidOnes) {
  const std::string message = ErrorOf("poke", TestShape());
  EXPECT_NE(message.find("'poke'"), std::string::npos) << message;
  for (const char* name : {"press", "sweep", "tap"}) {
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
}

TEST(BuiltInTrajectoryTest, InvalidShapesNameTheField) {
  struct Case {
    const char* field;
    void (*spoil)(MotionShape&);
  };
  const Case cases[] = {
      {"start_m", [](MotionShape& s) { s.start_m.x() = std::nan(""); }},
      {"depth_m", [](MotionShape& s) { s.depth_m = -0.01; }},
      {"sweep_m", [](MotionShape& s) { s.sweep_m = std::numeric_limits<double>::infinity(); }},
      {"period_s", [](MotionShape& s) { s.period_s = 0.0; }},
      {"cycles", [](MotionShape& s) { s.cycles = 0; }},
  };
  for (const Case& c : cases) {
    MotionShape shape = TestShape();
    c.spoil(shape);
    const std::string message = ErrorOf("press", shape);
    EXPECT_NE(message.find(std::string("motion.") + c.field), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace cosmems
