// `cosmems sweep`: outputs against closed forms across a sweep, the same rows on any number of
// workers and shards, resume, refusal before any sample, and failures as rows.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <thread>

#include "cli_test_support.hpp"
#include "sweep_runner.hpp"

namespace cosmems::testing {
namespace sweep_cli_test {

using Json = nlohmann::json;

std::string TextOf(const std::filesystem::path& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// A PNG drawn by gnuplot, which the set-up installs: its signature.
void ExpectPng(const std::filesystem::path& path) {
  ASSERT_TRUE(std::filesystem::exists(path)) << path;
  EXPECT_EQ(TextOf(path).substr(1, 3), "PNG");
}

// The rows of samples.jsonl by index, without the fields that time the run (they differ from
// run to run, the physics does not).
std::map<std::int64_t, Json> Rows(const std::filesystem::path& directory) {
  std::map<std::int64_t, Json> rows;
  for (const std::string& line : ReadLines(directory / "samples.jsonl")) {
    Json row = Json::parse(line);
    if (row["result"].is_object()) {
      for (const char* timing : {"wall_time_s", "step_time_us", "tick_time_us"}) {
        row["result"].erase(timing);
      }
    }
    const auto index = row["index"].get<std::int64_t>();
    EXPECT_TRUE(rows.emplace(index, row).second) << "index " << index << " twice";
  }
  return rows;
}

// The built binary started with `args` (stdout to /dev/null, stderr to `err` when given), under
// each resource limit of `limits` (RLIMIT_FSIZE: a write past it fails as on a full disk).
pid_t Spawn(const std::vector<std::string>& args, const std::filesystem::path& err = {},
            const std::vector<std::pair<int, rlim_t>>& limits = {}) {
  const pid_t child = fork();
  if (child != 0) return child;
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  freopen("/dev/null", "w", stdout);
  if (!err.empty()) freopen(err.c_str(), "w", stderr);
  signal(SIGXFSZ, SIG_IGN);  // a write past RLIMIT_FSIZE fails with EFBIG, not a signal
  for (const auto& [resource, bound] : limits) {
    const rlimit limit{bound, bound};
    setrlimit(resource, &limit);
  }
  execv(argv[0], argv.data());
  _exit(127);
}

// The exit status of a child, -1 when a signal ended it.
int ExitStatus(pid_t child) {
  int status = 0;
  waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Every file of a folder and its text: what a refused command must leave as it was.
std::map<std::string, std::string> Snapshot(const std::filesystem::path& directory) {
  std::map<std::string, std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    files[entry.path().filename().string()] = TextOf(entry.path());
  }
  return files;
}

Json Sweep(std::vector<std::string> args) {
  args.insert(args.begin(), "sweep");
  args.push_back("--json");
  const CliOutcome outcome = Cli(args);
  EXPECT_EQ(outcome.code, 0) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  return Json::parse(outcome.out);
}

// Euler-Bernoulli: the tip deflection P L^3 / (3 E I) of the `cantilever` scene at each length
// of a grid (the Hermite element is exact for a tip load: 1e-9 is round-off of the solve).
TEST(SweepCliTest, TipDeflectionFollowsLengthCubedOverAGrid) {
  const TempDirectory dir;
  const Json summary = Sweep({"cantilever", "--vary", "structure.length=100e-6:300e-6:5", "--spec",
                              "max_deflection<=1.5e-7", "--out", dir.path().string()});
  EXPECT_EQ(summary["samples"], 5);
  EXPECT_EQ(summary["failed"], 0);
  const double ei = 169e9 * 20e-6 * std::pow(2e-6, 3) / 12.0;
  int within = 0;
  for (const auto& [index, row] : Rows(dir.path())) {
    const double length = row["parameters"]["structure.length"].get<double>();
    EXPECT_NEAR(length, 100e-6 + 50e-6 * index, 1e-18);
    const double expected = 1e-7 * std::pow(length, 3) / (3.0 * ei);
    const double uy = row["result"]["tip_displacement"][1].get<double>();
    EXPECT_NEAR(-uy / expected, 1.0, 1e-9) << length;
    within += expected <= 1.5e-7 ? 1 : 0;
  }
  // The yield: the lengths whose deflection meets the spec (100, 150 and 200 um).
  EXPECT_EQ(within, 3);
  EXPECT_DOUBLE_EQ(summary["yield"].get<double>(), 0.6);
  // d(max_deflection)/dL by least squares over the grid: the chord slope of L^3 fitted by a
  // line, (sum (L - mean)(y)) / sum (L - mean)^2, computed here from the closed form.
  double mean = 200e-6, num = 0.0, den = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double l = 100e-6 + 50e-6 * i;
    num += (l - mean) * 1e-7 * l * l * l / (3.0 * ei);
    den += (l - mean) * (l - mean);
  }
  EXPECT_NEAR(
      summary["sensitivities"]["max_deflection"]["structure.length"].get<double>() / (num / den),
      1.0, 1e-8);
  EXPECT_EQ(ReadLines(dir.path() / "samples.csv").size(), 6u);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "summary.json"));
  // The curve of the spec's field over the length, with the bound's line.
  EXPECT_EQ(ReadLines(dir.path() / "plot_max_deflection.dat").size(), 5u);
  ExpectContains(TextOf(dir.path() / "plot_max_deflection.gp"), "first 1.5e-07");
  ExpectPng(dir.path() / "plot_max_deflection.png");
}

// Two grid keys make a map, drawn keys a histogram with the spec's bound; --plot picks fields.
TEST(SweepCliTest, PlotsAMapOrAHistogram) {
  const TempDirectory map("_map"), histogram("_histogram");
  Sweep({"cantilever", "--vary", "structure.length=100e-6:300e-6:3", "--vary",
         "structure.thickness=[1.5e-6, 2e-6]", "--plot", "max_stress_pa", "--out",
         map.path().string()});
  // Three scans of the first key, two points each, a blank line between scans.
  EXPECT_EQ(ReadLines(map.path() / "plot_max_stress_pa.dat").size(), 8u);
  ExpectContains(TextOf(map.path() / "plot_max_stress_pa.gp"), "with pm3d");
  ExpectPng(map.path() / "plot_max_stress_pa.png");
  Sweep({"cantilever-modal", "--vary", "structure.thickness=normal:2e-6:0.05e-6", "--samples", "40",
         "--spec", "frequencies_hz[0]<70000", "--out", histogram.path().string()});
  EXPECT_EQ(ReadLines(histogram.path() / "plot_frequencies_hz_0.dat").size(), 40u);
  ExpectContains(TextOf(histogram.path() / "plot_frequencies_hz_0.gp"), "set arrow from 70000,");
  ExpectPng(histogram.path() / "plot_frequencies_hz_0.png");
}

// A parametric device's design key varies like any other: the folded-flexure's shuttle moves
// F / k with k = 24 E I / L^3 over a grid of beam lengths (1e-9: the guided beams' Hermite
// elements are exact for end loads).
TEST(SweepCliTest, ADevicesDesignParameterVaries) {
  const TempDirectory dir;
  Sweep({"folded-flexure", "--vary", "structure.beam_length=80e-6:120e-6:3", "--out",
         dir.path().string()});
  const double ei = 160e9 * 2e-6 * std::pow(2e-6, 3) / 12.0;
  const auto rows = Rows(dir.path());
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& [index, row] : rows) {
    const double length = row["parameters"]["structure.beam_length"].get<double>();
    const double x = row["result"]["bodies"]["shuttle"]["displacement"][0].get<double>();
    EXPECT_NEAR(x / (1e-6 * std::pow(length, 3) / (24.0 * ei)), 1.0, 1e-9) << length;
  }
}

// f1 = (1.8751^2 / 2 pi) sqrt(E I / (rho A)) / L^2 is proportional to the thickness t, so a
// normal spread of t gives f1 the mean c mu_t and standard deviation c sigma_t. The sample's
// mean and spread must match within four of their standard errors (n = 400 Monte Carlo draws).
TEST(SweepCliTest, MonteCarloSpreadOfTheFirstFrequencyFollowsTheThickness) {
  const double mu = 2e-6, sigma = 0.04e-6;
  const int n = 400;
  const Json summary =
      Sweep({"cantilever-modal", "--vary", "structure.thickness=normal:2e-6:0.04e-6", "--samples",
             std::to_string(n), "--seed", "7", "--set", "analysis.count=1"});
  ASSERT_EQ(summary["failed"], 0);
  const double beta = 1.875104068711961, length = 200e-6;
  const double c = beta * beta / (2.0 * 3.14159265358979323846 * length * length) *
                   std::sqrt(169e9 / (12.0 * 2330.0));  // f1 = c t
  const Json& f1 = summary["outputs"]["frequencies_hz[0]"];
  EXPECT_NEAR(f1["mean"].get<double>(), c * mu, 4.0 * c * sigma / std::sqrt(n));
  EXPECT_NEAR(f1["std"].get<double>(), c * sigma, 4.0 * c * sigma / std::sqrt(2.0 * (n - 1)));
  // The sensitivity is the slope c itself, to 1e-3: the model's f1 departs from c t by its
  // discretisation error and by rotary inertia, of order (t / L)^2 = 1e-4.
  EXPECT_NEAR(
      summary["sensitivities"]["frequencies_hz[0]"]["structure.thickness"].get<double>() / c, 1.0,
      1e-3);
}

// The rows are the same, row for row by index, on 1 or 2 threads and as two shards merged.
TEST(SweepCliTest, ThreadsAndShardsGiveTheSameRows) {
  const TempDirectory one("_one"), two("_two"), shards("_shards");
  const std::vector<std::string> sweep = {"cantilever",
                                          "--vary",
                                          "structure.length=uniform:150e-6:250e-6",
                                          "--vary",
                                          "structure.thickness=[1.5e-6, 2e-6]",
                                          "--samples",
                                          "6",
                                          "--method",
                                          "lhs"};
  auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = sweep;
    args.insert(args.end(), more.begin(), more.end());
    return Sweep(args);
  };
  with({"--threads", "1", "--out", one.path().string()});
  with({"--threads", "2", "--out", two.path().string()});
  EXPECT_EQ(with({"--shard", "1/2", "--out", shards.path().string()})["samples"], 6);
  const Json merged = with({"--shard", "2/2", "--out", shards.path().string()});
  EXPECT_EQ(merged["samples"], 12);
  const std::map<std::int64_t, Json> reference = Rows(one.path());
  ASSERT_EQ(reference.size(), 12u);
  EXPECT_EQ(Rows(two.path()), reference);
  EXPECT_EQ(Rows(shards.path()), reference);
}

// A sweep killed midway resumes from its folder: the finished rows stay as they were (their
// timings too: they were not run again), the rest are run, no index twice. Each sample (a
// 1000-element modal analysis, about 25 ms) outlasts the 5 ms polls many times over, so the
// kill lands while samples remain.
TEST(SweepCliTest, AKilledSweepResumesWithoutRedoingOrDuplicatingRows) {
  const TempDirectory dir;
  const std::string out = dir.path().string();
  const std::vector<std::string> args = {COSMEMS_BINARY,
                                         "sweep",
                                         "cantilever-modal",
                                         "--vary",
                                         "model.elements=1000:1190:20",
                                         "--threads",
                                         "1",
                                         "--out",
                                         out};
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    freopen("/dev/null", "w", stdout);
    execv(argv[0], argv.data());
    _exit(127);
  }
  // Killed once three samples are written (unless it ended first: then the test fails).
  int status = 0;
  bool ended = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (ReadLines(dir.path() / "samples.jsonl").size() < 3 &&
         std::chrono::steady_clock::now() < deadline && !ended) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ended = waitpid(child, &status, WNOHANG) == child;
  }
  if (!ended) {
    kill(child, SIGKILL);
    waitpid(child, &status, 0);
  }
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it was killed, status " << status;
  // As if the kill had cut the next row short.
  std::ofstream(dir.path() / "samples.jsonl", std::ios::app) << "{\"index\": 19, \"param";
  std::map<std::int64_t, Json> before;
  for (const std::string& line : ReadLines(dir.path() / "samples.jsonl")) {
    if (line.back() == '}') {
      const Json row = Json::parse(line);
      before.emplace(row["index"].get<std::int64_t>(), row);
    }
  }
  ASSERT_GE(before.size(), 3u);
  ASSERT_LT(before.size(), 20u);

  const Json summary =
      Sweep({"cantilever-modal", "--vary", "model.elements=1000:1190:20", "--out", out});
  EXPECT_EQ(summary["samples"], 20);
  std::set<std::int64_t> indices;
  for (const std::string& line : ReadLines(dir.path() / "samples.jsonl")) {
    const Json row = Json::parse(line);  // every line whole
    EXPECT_TRUE(indices.insert(row["index"].get<std::int64_t>()).second);
    const auto kept = before.find(row["index"].get<std::int64_t>());
    if (kept != before.end()) {
      EXPECT_EQ(row, kept->second);
    }
  }
  EXPECT_EQ(indices.size(), 20u);
  // Another sweep in the same folder is refused, not mixed in.
  ExpectContains(
      InvalidInput({"sweep", "cantilever-modal", "--vary", "model.elements=20:40:2", "--out", out}),
      "holds another sweep");
}

// Shards started together into one folder (the documented workflow for job arrays): every
// line of samples.jsonl is one whole row, every index is there once, and the sweep run there
// afterwards finds nothing to run. 200 folded-flexure rows of a few kilobytes each, written by
// four processes at once.
TEST(SweepCliTest, ConcurrentShardsIntoOneFolderKeepEveryRowWhole) {
  const TempDirectory dir;
  const std::string out = dir.path().string();
  const std::vector<std::string> sweep = {"folded-flexure", "--vary",
                                          "structure.beam_length=80e-6:120e-6:200", "--out", out};
  constexpr int kShards = 4, kSamples = 200;
  std::vector<pid_t> shards;
  for (int k = 1; k <= kShards; ++k) {
    std::vector<std::string> args = {COSMEMS_BINARY, "sweep"};
    args.insert(args.end(), sweep.begin(), sweep.end());
    args.insert(args.end(), {"--threads", "1", "--shard", std::to_string(k) + "/4"});
    shards.push_back(Spawn(args, dir.path() / ("err" + std::to_string(k) + ".txt")));
  }
  for (int k = 0; k < kShards; ++k) {
    EXPECT_EQ(ExitStatus(shards[k]), 0)
        << TextOf(dir.path() / ("err" + std::to_string(k + 1) + ".txt"));
  }
  std::map<std::int64_t, int> seen;
  const std::vector<std::string> lines = ReadLines(dir.path() / "samples.jsonl");
  for (const std::string& line : lines) {
    const Json row = Json::parse(line, nullptr, false);
    ASSERT_FALSE(row.is_discarded()) << "not a row: " << line.substr(0, 200);
    ++seen[row["index"].get<std::int64_t>()];
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(kSamples));
  for (const auto& [index, count] : seen) EXPECT_EQ(count, 1) << "index " << index;
  EXPECT_EQ(Sweep(sweep)["samples"], kSamples);
  EXPECT_EQ(ReadLines(dir.path() / "samples.jsonl").size(), lines.size());
}

// A line that is not a row (two rows joined by an older cosmems, a hand's edit) is skipped with
// a warning naming it, and the samples it held run again.
TEST(SweepCliTest, ACorruptLineIsSkippedWithAWarningAndItsSampleRunsAgain) {
  const TempDirectory dir;
  const std::vector<std::string> sweep = {
      "sweep", "cantilever",        "--vary", "structure.length=100e-6:300e-6:5",
      "--out", dir.path().string(), "--json"};
  ASSERT_EQ(Cli(sweep).code, 0);
  std::vector<std::string> lines = ReadLines(dir.path() / "samples.jsonl");
  ASSERT_EQ(lines.size(), 5u);
  const std::int64_t lost = Json::parse(lines[1])["index"], joined = Json::parse(lines[2])["index"];
  lines[1] = lines[1].substr(0, lines[1].size() / 2) + lines[2];
  lines.erase(lines.begin() + 2);
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  WriteFile(dir.path() / "samples.jsonl", text);

  const CliOutcome resumed = Cli(sweep);
  ASSERT_EQ(resumed.code, 0) << resumed.err;
  ExpectContains(resumed.err, "samples.jsonl line 2 is not a sample row");
  EXPECT_EQ(Json::parse(resumed.out)["samples"], 5);
  std::set<std::int64_t> indices;
  for (const std::string& line : ReadLines(dir.path() / "samples.jsonl")) {
    const Json row = Json::parse(line, nullptr, false);
    if (!row.is_discarded()) indices.insert(row["index"].get<std::int64_t>());
  }
  EXPECT_EQ(indices, (std::set<std::int64_t>{0, 1, 2, 3, 4})) << lost << " " << joined;
}

// sweep.json records the scene's text (by its hash) and the program's version: a resume after
// the scene was edited, or by another version, is refused naming what changed, and the folder
// is left as it was.
TEST(SweepCliTest, AResumeAfterTheSceneOrTheVersionChangedIsRefused) {
  const TempDirectory dir("_scene"), out("_out");
  const std::filesystem::path scene = dir.path() / "beam.toml";
  const std::string text = Cli({"show", "cantilever"}).out;
  const std::size_t modulus = text.find("young_modulus = 169e9");
  ASSERT_NE(modulus, std::string::npos);
  WriteFile(scene, text);
  const std::vector<std::string> sweep = {"sweep",  scene.string(),
                                          "--vary", "structure.length=100e-6:300e-6:3",
                                          "--out",  out.path().string()};
  ASSERT_EQ(Cli(sweep).code, 0);
  std::map<std::string, std::string> before = Snapshot(out.path());

  std::string edited = text;
  edited.replace(modulus, std::string("young_modulus = 169e9").size(), "young_modulus = 160e9");
  WriteFile(scene, edited);
  ExpectContains(InvalidInput(sweep), "scene_text_hash (the scene's text)");
  EXPECT_TRUE(Snapshot(out.path()) == before);

  WriteFile(scene, text);
  Json recorded = Json::parse(TextOf(out.path() / "sweep.json"));
  EXPECT_EQ(recorded["version"], COSMEMS_VERSION);
  recorded["version"] = "0.0.1";
  WriteFile(out.path() / "sweep.json", recorded.dump(2) + "\n");
  before = Snapshot(out.path());
  ExpectContains(InvalidInput(sweep), "version: \"0.0.1\" there, \"" COSMEMS_VERSION "\" now");
  EXPECT_TRUE(Snapshot(out.path()) == before);
}

// sweep.json, summary.json, samples.csv, the plots and run's --out files replace a symbolic
// link in their place instead of writing through it; samples.jsonl, appended to, refuses one.
TEST(SweepCliTest, OutputsNeverWriteThroughASymbolicLink) {
  const TempDirectory dir;
  const std::filesystem::path precious = dir.path() / "precious.txt";
  WriteFile(precious, "precious\n");
  const std::filesystem::path sweep = dir.path() / "sweep", run = dir.path() / "run",
                              appended = dir.path() / "appended";
  for (const auto& folder : {sweep, run, appended}) std::filesystem::create_directories(folder);
  for (const char* name : {"summary.json", "samples.csv", "plot_max_deflection.dat",
                           "plot_max_deflection.gp", "plot_max_deflection.png"}) {
    std::filesystem::create_symlink(precious, sweep / name);
  }
  std::filesystem::create_symlink(precious, run / "deflection.csv");
  std::filesystem::create_symlink(precious, appended / "samples.jsonl");

  Sweep({"cantilever", "--vary", "structure.length=100e-6:300e-6:3", "--out", sweep.string()});
  ASSERT_EQ(Cli({"run", "cantilever", "--out", run.string()}).code, 0);
  EXPECT_EQ(TextOf(precious), "precious\n");
  for (const std::filesystem::path& file :
       {sweep / "summary.json", sweep / "samples.csv", sweep / "plot_max_deflection.png",
        run / "deflection.csv"}) {
    EXPECT_FALSE(std::filesystem::is_symlink(file)) << file;
    EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
  }
  EXPECT_EQ(Json::parse(TextOf(sweep / "summary.json"))["samples"], 3);
  EXPECT_EQ(ReadLines(run / "deflection.csv").size(), 22u);  // the header, 21 nodes
  EXPECT_EQ(ReadLines(sweep / "samples.csv").size(), 4u);

  const CliOutcome refused = Cli({"sweep", "cantilever", "--vary",
                                  "structure.length=100e-6:300e-6:3", "--out", appended.string()});
  EXPECT_EQ(refused.code, 1);
  ExpectContains(refused.err, (appended / "samples.jsonl").string() + ": a symbolic link");
  EXPECT_EQ(TextOf(precious), "precious\n");
}

// A write that fails (here past a limit on file sizes, as on a full disk) is exit status 1
// naming the file and the system's reason, not "invalid input"; the file that was there before
// is left whole and no temporary remains.
TEST(SweepCliTest, AFailedWriteIsExitOneNamingTheFileAndTheReason) {
  const TempDirectory dir;
  const std::filesystem::path run = dir.path() / "run", sweep = dir.path() / "sweep";
  ASSERT_EQ(Cli({"run", "cantilever", "--out", run.string()}).code, 0);
  const std::map<std::string, std::string> before = Snapshot(run);
  const std::filesystem::path err = dir.path() / "err.txt";
  // 2001 rows of seven numbers: far past 16 kB.
  EXPECT_EQ(ExitStatus(Spawn({COSMEMS_BINARY, "run", "cantilever", "--set", "model.elements=2000",
                              "--out", run.string()},
                             err, {{RLIMIT_FSIZE, 16384}})),
            1);
  ExpectContains(TextOf(err), (run / "deflection.csv").string() + ": cannot write: File too large");
  EXPECT_TRUE(Snapshot(run) == before);
  // The sweep's rows: a few kilobytes each, the fifth past the limit.
  EXPECT_EQ(ExitStatus(Spawn({COSMEMS_BINARY, "sweep", "folded-flexure", "--vary",
                              "structure.beam_length=80e-6:120e-6:20", "--out", sweep.string()},
                             err, {{RLIMIT_FSIZE, 16384}})),
            1);
  ExpectContains(TextOf(err),
                 (sweep / "samples.jsonl").string() + ": cannot write: File too large");
}

// A sample that throws (here out of memory: a 100000-element 3-D modal analysis in 500 MB of
// address space) is a row with its error, and the sweep goes on to its end: it used to stop the
// whole sweep (exit 1, "out of memory"). The sanitizers reserve terabytes of address space.
TEST(SweepCliTest, ASampleThatThrowsIsARowWithItsError) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "an address-space limit and a sanitizer's shadow memory do not mix";
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
  GTEST_SKIP() << "an address-space limit and a sanitizer's shadow memory do not mix";
#endif
#endif
  const TempDirectory dir;
  const std::filesystem::path out = dir.path() / "out", err = dir.path() / "err.txt";
  ASSERT_EQ(ExitStatus(Spawn({COSMEMS_BINARY, "sweep", "cantilever", "--vary",
                              "model.elements=[20, 100000]", "--set", "model.dimension=3", "--set",
                              "analysis.type=modal", "--threads", "2", "--out", out.string()},
                             err, {{RLIMIT_AS, rlim_t{500} << 20}})),
            0)
      << TextOf(err);
  const std::map<std::int64_t, Json> rows = Rows(out);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows.at(0)["status"], "ok");
  EXPECT_EQ(rows.at(1)["status"], "error: out of memory");
  EXPECT_TRUE(rows.at(1)["result"].is_null());
  EXPECT_EQ(Json::parse(TextOf(out / "summary.json"))["failed"], 1);
}

// The number of samples is bounded before anything of their size is allocated (an LHS sweep's
// strata): exit 2 naming --samples and the limit.
TEST(SweepCliTest, TheNumberOfSamplesIsBounded) {
  ExpectContains(
      InvalidInput({"sweep", "cantilever", "--vary", "structure.length=uniform:1e-4:2e-4",
                    "--samples", "1000000000000", "--method", "lhs"}),
      "--samples = 1000000000000: the sweep would have 1000000000000 samples, above "
      "the limit of 10000000");
}

TEST(SweepCliTest, AnInvalidSweepIsRefusedBeforeAnySampleRuns) {
  const TempDirectory dir;
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", "structure.lenght=1e-4:2e-4:3",
                               "--out", dir.path().string()}),
                 "structure.lenght");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "samples.jsonl"));
  // The last grid value is the bad one: every value is checked first.
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", "model.elements=[8, 16, 0]"}),
                 "model.elements");
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", "structure.length=normal:1e-4"}),
                 "--vary structure.length=normal:1e-4");
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", "structure.length=1e-4:2e-4:3",
                               "--spec", "max_deflection=>1"}),
                 "--spec max_deflection=>1");
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", "structure.length=1e-4:2e-4:3",
                               "--shard", "3/2"}),
                 "--shard 3/2");
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", "structure.length=1e-4:2e-4:3",
                               "--method", "halton"}),
                 "halton");
  ExpectContains(InvalidInput({"sweep", "cantilever"}), "nothing to sweep");
  ExpectContains(InvalidInput({"sweep", "cantilever", "--vary", " =1e-4:2e-4:3"}),
                 "--vary  =1e-4:2e-4:3: expected KEY=SPEC");
  // Blanks around the key and the spec are dropped, as --set drops them.
  EXPECT_EQ(Sweep({"cantilever", "--vary", " structure.length = 1e-4:2e-4:3 "})["samples"], 3);
}

// A drawn value the scene refuses (a negative length) is a row with its status; the sweep
// runs the others.
TEST(SweepCliTest, ASampleTheSceneRefusesIsARowAndTheSweepGoesOn) {
  const TempDirectory dir;
  const Json summary = Sweep({"cantilever", "--vary", "structure.length=normal:50e-6:60e-6",
                              "--samples", "20", "--out", dir.path().string()});
  int invalid = 0;
  for (const auto& [index, row] : Rows(dir.path())) {
    const std::string status = row["status"];
    if (status == "ok") {
      EXPECT_GT(row["parameters"]["structure.length"].get<double>(), 0.0);
    } else {
      ++invalid;
      ExpectContains(status, "structure.length");
      EXPECT_TRUE(row["result"].is_null());
    }
  }
  EXPECT_GT(invalid, 0);
  EXPECT_LT(invalid, 20);
  EXPECT_EQ(summary["failed"], invalid);
  EXPECT_EQ(summary["samples"], 20);
}

// A scene file whose name is not UTF-8 (Latin-1 names on an old cluster): each result names
// it, and a row that cannot be written as JSON used to throw and stop the whole sweep. Its rows
// are written, the name's stray byte as U+FFFD.
TEST(SweepCliTest, ASceneNameThatIsNotUtf8StopsNoSample) {
  const TempDirectory dir("_scene"), out("_out");
  const std::filesystem::path scene = dir.path() / "beam-\xe9.toml";
  WriteFile(scene, Cli({"show", "cantilever"}).out);
  const CliOutcome outcome =
      Cli({"sweep", scene.string(), "--vary", "structure.length=100e-6:300e-6:3", "--threads", "2",
           "--out", out.path().string(), "--json"});
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  EXPECT_EQ(Json::parse(outcome.out)["failed"], 0);
  const std::map<std::int64_t, Json> rows = Rows(out.path());
  ASSERT_EQ(rows.size(), 3u);
  ExpectContains(rows.at(0)["result"]["scene"].get<std::string>(), "beam-\xef\xbf\xbd.toml");
}

// On a terminal a progress line counts the samples as they finish, each overwriting the last.
TEST(SweepCliTest, DrawsAProgressLine) {
  internal::SweepRequest request;
  request.scene = "cantilever";
  request.vary = {{"structure.length", "100e-6:300e-6:3"}};
  request.threads = 1;
  std::ostringstream out, err;
  ASSERT_EQ(internal::RunSweep(request, out, err, true), 0);
  ExpectContains(err.str(), "\rsweep: 1/3 samples, 0 failed, ");
  ExpectContains(err.str(), "\rsweep: 3/3 samples, 0 failed, ");
  EXPECT_EQ(err.str().back(), '\n');
  ExpectContains(out.str(), "sweep: 3 samples, 0 failed");
}

// A scene's [sweep] table is the sweep's default; `run` ignores it.
TEST(SweepCliTest, ASceneCarriesItsSweep) {
  const TempDirectory dir;
  const std::filesystem::path scene = dir.path() / "swept.toml";
  const CliOutcome shown = Cli({"show", "cantilever"});
  WriteFile(scene, shown.out +
                       "\n[sweep]\nmethod = \"sobol\"\nsamples = 4\nseed = 3\n"
                       "specs = [\"max_deflection<=1.5e-7\"]\n"
                       "[sweep.vary]\n\"structure.length\" = \"uniform:150e-6:250e-6\"\n");
  const Json summary = Sweep({scene.string()});
  EXPECT_EQ(summary["samples"], 4);
  EXPECT_TRUE(summary.contains("yield"));
  // The command line replaces the table's spec of a key and its sample count.
  const Json replaced =
      Sweep({scene.string(), "--samples", "2", "--vary", "structure.length=uniform:1e-4:2e-4"});
  EXPECT_EQ(replaced["samples"], 2);
  EXPECT_LE(replaced["outputs"]["max_deflection"]["max"].get<double>(), 1.2e-7);
  EXPECT_EQ(RunJson({scene.string()})["status"], "ok");
  WriteFile(scene, shown.out + "\n[sweep]\nsamples = \"many\"\n");
  ExpectContains(InvalidInput({"sweep", scene.string()}), "sweep.samples");
}

#ifdef COSMEMS_MPIEXEC
// mpirun with 3 ranks (rank 0 dispatching to two) gives the threaded run's rows; an invalid
// sweep fails on every rank with the exit status 2 and names its key. OpenMPI refuses root and
// more ranks than cores unless told (the CI machine: root, 2 cores).
int Mpirun(const std::string& args, const std::filesystem::path& err,
           const std::string& prefix = "") {
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  const std::string command = prefix + COSMEMS_MPIEXEC + " -n 3 " + COSMEMS_BINARY + " sweep " +
                              args + " > /dev/null 2> " + err.string();
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(SweepCliTest, MpiRanksGiveTheThreadedRows) {
  const TempDirectory threads("_threads"), ranks("_ranks");
  const std::string sweep =
      "cantilever-modal --vary structure.length=uniform:150e-6:250e-6 --vary "
      "model.elements=[10,20] --samples 5 --method sobol";
  Sweep({"cantilever-modal", "--vary", "structure.length=uniform:150e-6:250e-6", "--vary",
         "model.elements=[10,20]", "--samples", "5", "--method", "sobol", "--out",
         threads.path().string()});
  const std::filesystem::path err = ranks.path() / "err.txt";
  ASSERT_EQ(Mpirun(sweep + " --out " + (ranks.path() / "out").string(), err), 0) << TextOf(err);
  const Json summary = Json::parse(std::ifstream(ranks.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["workers"], 2);
  EXPECT_EQ(summary["samples"], 10);
  EXPECT_EQ(Rows(ranks.path() / "out"), Rows(threads.path()));
  EXPECT_EQ(Mpirun("cantilever --vary structure.lenght=1e-4:2e-4:3", err), 2);
  ExpectContains(TextOf(err), "structure.lenght");
}

// A rank that dies (killed here once three rows are written) ends the job: mpirun exits
// non-zero instead of rank 0 waiting for the dead rank's row, and the resume finishes the sweep.
// The deadline only keeps a hang from blocking the suite.
TEST(SweepCliTest, ADeadRankEndsTheJobAndTheResumeFinishes) {
  const TempDirectory dir;
  const std::string out = (dir.path() / "out").string();
  const std::string sweep =
      "cantilever-modal --vary model.elements=1000:1990:100 --threads 1 --out " + out;
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  setenv("OMPI_MCA_rmaps_base_oversubscribe", "1", 1);
  const pid_t mpirun = Spawn(
      {"/bin/sh", "-c",
       std::string("exec ") + COSMEMS_MPIEXEC + " -n 3 " + COSMEMS_BINARY + " sweep " + sweep},
      dir.path() / "err.txt");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  while (ReadLines(dir.path() / "out" / "samples.jsonl").size() < 3 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // mpirun's children are the ranks: the last one started goes.
  std::ifstream children("/proc/" + std::to_string(mpirun) + "/task/" + std::to_string(mpirun) +
                         "/children");
  pid_t rank = 0;
  for (pid_t child; children >> child;) rank = child;
  ASSERT_GT(rank, 0) << TextOf(dir.path() / "err.txt");
  kill(rank, SIGKILL);
  int status = 0;
  bool ended = false;
  while (!ended && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ended = waitpid(mpirun, &status, WNOHANG) == mpirun;
  }
  if (!ended) {
    kill(mpirun, SIGKILL);
    waitpid(mpirun, &status, 0);
  }
  ASSERT_TRUE(ended) << "mpirun still waited after a rank died";
  EXPECT_FALSE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  const Json summary =
      Sweep({"cantilever-modal", "--vary", "model.elements=1000:1990:100", "--out", out});
  EXPECT_EQ(summary["samples"], 100);
  EXPECT_EQ(Rows(dir.path() / "out").size(), 100u);
}

// A worker's sample whose row could not be written as JSON (the scene's name not UTF-8) threw
// out of the worker, which left MPI while rank 0 waited for its row for ever: `timeout` turns
// such a hang into a failure (status 124, or 137 when mpirun ignores the TERM). Now the rows
// come back and the sweep ends, with --out too (whose sweep.json names the scene).
TEST(SweepCliTest, AWorkerWhoseSampleThrowsDoesNotHangTheRanks) {
  const TempDirectory dir;
  const std::filesystem::path scene = dir.path() / "beam-\xe9.toml";
  WriteFile(scene, Cli({"show", "cantilever"}).out);
  const std::filesystem::path err = dir.path() / "err.txt", out = dir.path() / "out";
  const std::string sweep = "'" + scene.string() + "' --vary structure.length=100e-6:300e-6:4";
  const std::string guard = "timeout -k 10 300 ";
  ASSERT_EQ(Mpirun(sweep + " --json", err, guard), 0) << TextOf(err);
  ASSERT_EQ(Mpirun(sweep + " --out " + out.string(), err, guard), 0) << TextOf(err);
  EXPECT_EQ(Rows(out).size(), 4u);
  // The resume reads the name back as it was written.
  ASSERT_EQ(Mpirun(sweep + " --out " + out.string(), err, guard), 0) << TextOf(err);
}
#endif

// One device, one hand: a haptic scene on the OpenHaptics device is refused as a sweep (exit 2
// naming device.backend), before a sample runs; a paced one runs its samples one at a time
// whatever the threads asked, so that each measures the machine alone.
TEST(SweepCliTest, AHapticSweepNeverSharesADeviceAndRunsPacedSamplesOneAtATime) {
  const std::string refused =
      InvalidInput({"sweep", "cantilever-haptic", "--set", "device.backend=\"openhaptics\"",
                    "--vary", "structure.length=150e-6:200e-6:2", "--threads", "2"});
  ExpectContains(refused, "device.backend = \"openhaptics\"");

  const TempDirectory dir;
  const std::filesystem::path script = dir.path() / "short.csv";
  WriteFile(script, "time_s,x_m,y_m,z_m\n0.0,0.0,0.0,0.0\n0.03,0.0,-0.0001,0.0\n");
  const Json paced =
      Sweep({"cantilever-haptic", "--set", "device.trajectory=\"" + script.string() + "\"",
             "--vary", "structure.length=150e-6:200e-6:2", "--threads", "2"});
  EXPECT_EQ(paced["samples"], 2);
  EXPECT_EQ(paced["workers"], 1);
  const Json fast = Sweep(
      {"cantilever-haptic", "--set", "device.trajectory=\"" + script.string() + "\"", "--set",
       "device.realtime=false", "--vary", "structure.length=150e-6:200e-6:2", "--threads", "2"});
  EXPECT_EQ(fast["workers"], 2);
}

}  // namespace sweep_cli_test
}  // namespace cosmems::testing
