// A sweep's worker threads, each running whole analyses at once: beam statics and transients, a
// device's modes, samples that fail, and haptic sessions (each with its own device thread) side
// by side. Built under ThreadSanitizer with the command line, the session and the device layer
// instrumented (ThreadSanitizer.SweepThreads); the rows are checked against a one-thread run.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "cli_test_support.hpp"

namespace cosmems::testing {
namespace {

using Json = nlohmann::json;

// The rows of a sweep's --json output by index, timings left out (they differ run to run).
std::map<long, Json> RowsOf(const std::vector<std::string>& args) {
  const CliOutcome outcome = Cli(args);
  EXPECT_EQ(outcome.code, 0) << outcome.err;
  std::map<long, Json> rows;
  for (const std::string& line : ReadLines(std::filesystem::path(args.back()) / "samples.jsonl")) {
    Json row = Json::parse(line);
    if (row["result"].is_object()) {
      for (const char* timing :
           {"wall_time_s", "step_time_us", "tick_time_us", "realtime_factor",
            "stepping_realtime_factor", "physics", "deadline_misses", "rate_hz", "overruns"}) {
        row["result"].erase(timing);
      }
    }
    rows[row["index"].get<long>()] = row;
  }
  return rows;
}

// Each sweep on two threads and on one: the same rows, and TSan silent on the way.
void ExpectSameRowsOnTwoThreads(std::vector<std::string> args, std::size_t samples) {
  const TempDirectory one("_one"), two("_two");
  std::vector<std::string> on_one = args, on_two = args;
  on_one.insert(on_one.end(), {"--threads", "1", "--out", one.path().string()});
  on_two.insert(on_two.end(), {"--threads", "2", "--out", two.path().string()});
  const std::map<long, Json> expected = RowsOf(on_one), rows = RowsOf(on_two);
  EXPECT_EQ(rows.size(), samples);
  EXPECT_EQ(rows, expected);
}

// Drawn lengths, a quarter of them negative: those samples are rows with their errors.
TEST(SweepThreadTest, BeamStaticsWithFailingSamples) {
  ExpectSameRowsOnTwoThreads({"sweep", "cantilever", "--vary",
                              "structure.length=uniform:-100e-6:300e-6", "--samples", "8"},
                             8);
}

TEST(SweepThreadTest, BeamTransients) {
  ExpectSameRowsOnTwoThreads({"sweep", "cantilever", "--set", "analysis.type=\"transient\"",
                              "--set", "analysis.duration=2e-6", "--set", "analysis.time_step=1e-7",
                              "--vary", "structure.length=150e-6:200e-6:4"},
                             4);
}

TEST(SweepThreadTest, DeviceModes) {
  ExpectSameRowsOnTwoThreads(
      {"sweep", "folded-flexure", "--set", "analysis.type=\"modal\"", "--set", "model.elements=2",
       "--vary", "structure.beam_length=80e-6:120e-6:4"},
      4);
}

// Haptic sessions in the workers, each with its scripted device's thread (unpaced, so that the
// samples run at once and their histories are deterministic).
TEST(SweepThreadTest, HapticSessionsSideBySide) {
  const TempDirectory dir("_script");
  const std::filesystem::path script = dir.path() / "short.csv";
  WriteFile(script, "time_s,x_m,y_m,z_m\n0.0,0.0,0.0,0.0\n0.05,0.0,-0.002,0.0\n");
  ExpectSameRowsOnTwoThreads({"sweep", "cantilever-haptic", "--set", "device.realtime=false",
                              "--set", "device.trajectory=\"" + script.string() + "\"", "--vary",
                              "structure.length=150e-6:200e-6:4"},
                             4);
}

}  // namespace
}  // namespace cosmems::testing
