// Loop figures from known tick times.
#include "cosmems/haptics/loop_stats.hpp"

#include <gtest/gtest.h>

namespace cosmems {
namespace {

TEST(LoopStatsTest, RateQuantilesOverrunsAndDeadlineMisses) {
  LoopStatsRecorder recorder;
  recorder.Start(1e-3, /*paced=*/true, /*realtime=*/false);
  double t = 10.0;
  for (int i = 0; i < 1000; ++i) {
    const double compute_us = i < 990 ? 20.5 : 1500.0;  // 1 % of the ticks overrun
    recorder.Record(t, compute_us);
    t += i == 500 ? 2e-3 : 1e-3;  // one late tick
  }
  const LoopStats& s = recorder.stats();
  EXPECT_EQ(s.ticks, 1000u);
  EXPECT_NEAR(s.rate_hz, 999.0 / (999 * 1e-3 + 1e-3), 1e-6);
  EXPECT_EQ(s.deadline_misses, 1u);
  EXPECT_NEAR(s.period_max_us, 2000.0, 1e-6);
  EXPECT_EQ(s.overruns, 10u);
  EXPECT_DOUBLE_EQ(s.ComputeQuantileUs(0.5), 21.0);  // the bin's upper edge
  EXPECT_DOUBLE_EQ(s.ComputeQuantileUs(0.99), 21.0);
  EXPECT_DOUBLE_EQ(s.ComputeQuantileUs(1.0), 1500.0);
}

}  // namespace
}  // namespace cosmems
