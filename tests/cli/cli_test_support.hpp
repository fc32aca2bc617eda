#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_cli.hpp"

namespace cosmems::testing {

// A fresh directory per test under GoogleTest's temporary directory, removed afterwards.
class TempDirectory {
 public:
  /// A directory named after the running test; `suffix` tells apart several in one test.
  explicit TempDirectory(const std::string& suffix = "") {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->test_suite_name()) + "_" + test->name() + suffix;
    std::replace(name.begin(), name.end(), '/', '_');
    path_ = std::filesystem::path(::testing::TempDir()) / ("cosmems_" + name);
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline std::vector<std::string> ReadLines(const std::filesystem::path& path) {
  std::ifstream file(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  return lines;
}

inline void WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

inline long LineCount(const std::string& text) {
  return static_cast<long>(std::count(text.begin(), text.end(), '\n'));
}

// RunCli in process: its exit status and what it wrote on each stream.
struct CliOutcome {
  int code = -1;
  std::string out;
  std::string err;
};

inline CliOutcome Cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  CliOutcome outcome;
  outcome.code = RunCli(args, out, err);
  outcome.out = out.str();
  outcome.err = err.str();
  return outcome;
}

inline nlohmann::json RunJson(std::vector<std::string> args, int expected_code = 0) {
  args.insert(args.begin(), "run");
  args.push_back("--json");
  const CliOutcome outcome = Cli(args);
  EXPECT_EQ(outcome.code, expected_code) << outcome.err;
  EXPECT_EQ(outcome.err, "");
  return nlohmann::json::parse(outcome.out);  // throws unless stdout is exactly one JSON value
}

// Invalid input: exit status 2, nothing on stdout and exactly one line on stderr.
inline std::string InvalidInput(const std::vector<std::string>& args) {
  const CliOutcome outcome = Cli(args);
  EXPECT_EQ(outcome.code, 2);
  EXPECT_EQ(outcome.out, "");
  EXPECT_EQ(LineCount(outcome.err), 1) << outcome.err;
  EXPECT_EQ(outcome.err.rfind("cosmems: ", 0), 0u) << outcome.err;
  return outcome.err;
}

inline void ExpectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in:\n" << text;
}

}  // namespace cosmems::testing
