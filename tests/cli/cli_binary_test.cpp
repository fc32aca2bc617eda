// The built `cosmems` binary, for what only a real process shows: the exit status and which
// stream each line went to.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_support.hpp"

namespace cosmems {
namespace {

struct Process {
  int code = -1;
  std::string out;
  std::string err;
};

// Runs the binary with `args` (shell syntax), capturing stdout and stderr apart. COSMEMS_BINARY
// is its path from the folder CTest runs the tests in.
Process RunBinary(const std::string& args) {
  const testing::TempDirectory dir;
  const std::string err_path = (dir.path() / "stderr.txt").string();
  const std::string command = std::string(COSMEMS_BINARY) + " " + args + " 2>" + err_path;
  Process process;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "popen failed: " << command;
    return process;
  }
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) {
    process.out.append(buffer, n);
  }
  const int status = pclose(pipe);
  process.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  for (const std::string& line : testing::ReadLines(err_path)) process.err += line + "\n";
  return process;
}

TEST(CosmemsBinaryTest, JsonRunPrintsOneObjectOnStdoutAndExitsZero) {
  const Process process = RunBinary("run cantilever --json");
  EXPECT_EQ(process.code, 0);
  EXPECT_EQ(process.err, "");
  const nlohmann::json json = nlohmann::json::parse(process.out);
  EXPECT_EQ(json.at("status"), "ok");
  EXPECT_EQ(json.at("tip_displacement").size(), 3u);
}

TEST(CosmemsBinaryTest, ModalRunExitsZero) {
  const Process process = RunBinary("run cantilever --set analysis.type=modal --json");
  EXPECT_EQ(process.code, 0);
  EXPECT_EQ(nlohmann::json::parse(process.out).at("frequencies_hz").size(), 4u);
}

TEST(CosmemsBinaryTest, InvalidInputIsOneLineOnStderrAndExitTwo) {
  const Process process = RunBinary("run cantilever --json --set 'structure.length=-2e-6'");
  EXPECT_EQ(process.code, 2);
  EXPECT_EQ(process.out, "");
  EXPECT_EQ(process.err, "cosmems: --set: structure.length = -2e-06: must be positive\n");
}

TEST(CosmemsBinaryTest, AnUnknownSceneIsNamedOnStderrWithExitTwo) {
  const Process process = RunBinary("run no-such-scene");
  EXPECT_EQ(process.code, 2);
  EXPECT_EQ(process.out, "");
  EXPECT_EQ(process.err.rfind("cosmems: no-such-scene: neither an embedded scene (", 0), 0u)
      << process.err;
  EXPECT_NE(process.err.find(") nor a scene file\n"), std::string::npos) << process.err;
}

TEST(CosmemsBinaryTest, NumericalFailurePrintsTheJsonAndExitsThree) {
  // No pull-in below the bound (see RunCliTest.NumericalFailure...).
  const Process process = RunBinary("run cantilever-pullin --json --set analysis.voltage_max=10.0");
  EXPECT_EQ(process.code, 3);
  EXPECT_EQ(process.err, "");
  EXPECT_EQ(nlohmann::json::parse(process.out).at("status"), "not converged");
}

TEST(CosmemsBinaryTest, TransientRunExitsZeroAndUnstableOneExitsThree) {
  const Process release = RunBinary("run cantilever-release --json");
  EXPECT_EQ(release.code, 0);
  EXPECT_EQ(release.err, "");
  EXPECT_EQ(nlohmann::json::parse(release.out).at("steps"), 1000);
  // Central difference far above its stability limit overflows (see TransientCliTest).
  const Process unstable = RunBinary(
      "run cantilever-release --json --set analysis.integrator=central-difference "
      "--set model.modes=0");
  EXPECT_EQ(unstable.code, 3);
  EXPECT_EQ(unstable.err, "");
  EXPECT_EQ(nlohmann::json::parse(unstable.out).at("status"), "diverged (unstable time step?)");
}

TEST(CosmemsBinaryTest, UsageErrorIsOneLineOnStderrAndExitTwo) {
  const Process process = RunBinary("run");
  EXPECT_EQ(process.code, 2);
  EXPECT_EQ(process.out, "");
  EXPECT_EQ(testing::LineCount(process.err), 1) << process.err;
}

}  // namespace
}  // namespace cosmems
