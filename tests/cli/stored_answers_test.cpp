// Every case of tests/answers/cases.txt run in process and compared with the answers stored
// beside it (tests/answers/capture.sh): the JSON's every field and the --out folder's every CSV
// cell. The cases cover every embedded scene and each analysis it runs, so a change in how a
// structure is modelled cannot move a reported number unnoticed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_test_support.hpp"

namespace cosmems::testing {
namespace {

namespace fs = std::filesystem;

// Each number within this of the stored one, relative to the larger of its magnitude and its
// row's or array's (see Scale): well above the round-off of a reordered sum or factorisation
// (1e-13 ... 1e-10 on these models), well below any change of a model or a solver.
constexpr double kRelative = 1e-7;

// What depends on the machine or the moment, not the model: wall-clock figures (and what the
// haptic session derives from them: its rate unpaced, its ticks over a period), the counts of
// work done (Newton iterations, linear solves), the build's version.
bool Ignored(const std::string& key) {
  static const std::set<std::string> keys = {"version",
                                             "wall_time_s",
                                             "step_time_us",
                                             "tick_time_us",
                                             "rate_hz",
                                             "realtime_factor",
                                             "stepping_realtime_factor",
                                             "deadline_misses",
                                             "overruns",
                                             "newton_iterations",
                                             "solves"};
  return keys.count(key) != 0;
}

struct Case {
  std::string name;
  std::vector<std::string> args;  // run SCENE --set ... --json --out
};

// A failure names the case, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

fs::path AnswersDir() { return fs::path(COSMEMS_ANSWERS_DIR); }

std::vector<Case> ReadCases() {
  std::vector<Case> cases;
  std::ifstream file(AnswersDir() / "cases.txt");
  for (std::string line; std::getline(file, line);) {
    std::istringstream words(line);
    Case c;
    std::string scene;
    if (!(words >> c.name >> scene) || c.name[0] == '#') continue;
    c.args = {"run", scene};
    for (std::string setting; words >> setting;) {
      c.args.push_back("--set");
      c.args.push_back(setting);
    }
    cases.push_back(c);
  }
  return cases;
}

bool Close(double stored, double now, double scale) {
  if (std::isnan(stored) || std::isnan(now)) return std::isnan(stored) && std::isnan(now);
  if (std::isinf(stored) || std::isinf(now)) return stored == now;
  return std::abs(now - stored) <= kRelative * std::max(std::abs(stored), scale);
}

// The magnitude a number of an array is judged by: the array's largest (a component at the
// round-off of a vector's largest, such as a 3-D beam's deflection across its plane, carries no
// figure of its own).
double Scale(const nlohmann::json& array) {
  double scale = 0.0;
  for (const nlohmann::json& v : array) {
    if (v.is_number()) scale = std::max(scale, std::abs(v.get<double>()));
  }
  return scale;
}

void CompareJson(const nlohmann::json& stored, const nlohmann::json& now, const std::string& path,
                 double scale) {
  if (stored.is_number() && now.is_number()) {
    EXPECT_TRUE(Close(stored.get<double>(), now.get<double>(), scale))
        << path << ": stored " << stored.dump() << ", now " << now.dump();
    return;
  }
  ASSERT_EQ(stored.type_name(), now.type_name()) << path;
  if (stored.is_object()) {
    for (const auto& [key, value] : stored.items()) {
      if (Ignored(key)) continue;
      ASSERT_TRUE(now.contains(key)) << path << "." << key << " is gone";
      CompareJson(value, now[key], path + "." + key, 0.0);
    }
    for (const auto& [key, value] : now.items()) {
      EXPECT_TRUE(Ignored(key) || stored.contains(key)) << path << "." << key << " is new";
    }
  } else if (stored.is_array()) {
    ASSERT_EQ(stored.size(), now.size()) << path;
    const double array_scale = Scale(stored);
    for (std::size_t i = 0; i < stored.size(); ++i) {
      CompareJson(stored[i], now[i], path + "[" + std::to_string(i) + "]", array_scale);
    }
  } else {
    EXPECT_EQ(stored, now) << path;
  }
}

std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  std::istringstream row(line);
  for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
  return cells;
}

bool Number(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

// Whether two columns are components of one vector: their names differ only in the axis letter
// (ux and uy, rx_rad and rz_rad, shuttle_ux_m and shuttle_uz_m, fx_n and fz_n).
bool Components(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  int differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i]) continue;
    if (std::string("xyz").find(a[i]) == std::string::npos ||
        std::string("xyz").find(b[i]) == std::string::npos) {
      return false;
    }
    ++differ;
  }
  return differ == 1;
}

// A CSV file cell by cell: the header and every text cell exactly, each number within
// kRelative of the larger of itself and the largest stored magnitude of its column and of the
// other components of its vector (a column is one quantity over time or along the beam; a
// component at the round-off of the vector's largest, such as a bending mode's axial motion,
// carries no figure of its own).
void CompareCsv(const fs::path& stored_path, const fs::path& now_path) {
  const std::vector<std::string> stored = ReadLines(stored_path);
  const std::vector<std::string> now = ReadLines(now_path);
  const std::string name = stored_path.filename().string();
  ASSERT_EQ(stored.size(), now.size()) << name << ": rows";
  ASSERT_FALSE(stored.empty()) << name;
  const std::vector<std::string> header = Cells(stored[0]);
  ASSERT_EQ(header, Cells(now[0])) << name << ": header";
  std::vector<double> scale(header.size(), 0.0);
  for (std::size_t r = 1; r < stored.size(); ++r) {
    const std::vector<std::string> cells = Cells(stored[r]);
    for (std::size_t c = 0; c < cells.size() && c < scale.size(); ++c) {
      double v = 0.0;
      if (Number(cells[c], v) && std::isfinite(v)) scale[c] = std::max(scale[c], std::abs(v));
    }
  }
  int reported = 0;  // the first few differences, not a screenful
  for (std::size_t r = 1; r < stored.size() && reported < 5; ++r) {
    const std::vector<std::string> a = Cells(stored[r]);
    const std::vector<std::string> b = Cells(now[r]);
    ASSERT_EQ(a.size(), b.size()) << name << " row " << r;
    for (std::size_t c = 0; c < a.size(); ++c) {
      if (c < header.size() && Ignored(header[c])) continue;
      double x = 0.0, y = 0.0;
      double within = c < scale.size() ? scale[c] : 0.0;
      for (std::size_t k = 0; k < scale.size() && c < header.size(); ++k) {
        if (Components(header[c], header[k])) within = std::max(within, scale[k]);
      }
      const bool same = Number(a[c], x) && Number(b[c], y) ? Close(x, y, within) : a[c] == b[c];
      if (!same) {
        ADD_FAILURE() << name << " row " << r << " column "
                      << (c < header.size() ? header[c] : std::to_string(c)) << ": stored " << a[c]
                      << ", now " << b[c];
        ++reported;
      }
    }
  }
}

class StoredAnswers : public ::testing::TestWithParam<Case> {};

TEST_P(StoredAnswers, EveryNumberAsStored) {
  const Case& c = GetParam();
  const fs::path stored = AnswersDir() / c.name;
  TempDirectory out;
  std::vector<std::string> args = c.args;
  args.insert(args.end(), {"--json", "--out", out.path().string()});
  const CliOutcome outcome = Cli(args);
  ASSERT_EQ(outcome.code, 0) << outcome.err;
  std::ifstream answer(stored / "answer.json");
  ASSERT_TRUE(answer) << stored / "answer.json";
  CompareJson(nlohmann::json::parse(answer), nlohmann::json::parse(outcome.out), c.name, 0.0);
  std::set<std::string> stored_files, written_files;
  for (const fs::directory_entry& f : fs::directory_iterator(stored)) {
    if (f.path().extension() == ".csv") stored_files.insert(f.path().filename().string());
  }
  for (const fs::directory_entry& f : fs::directory_iterator(out.path())) {
    if (f.path().extension() == ".csv") written_files.insert(f.path().filename().string());
  }
  EXPECT_EQ(stored_files, written_files);
  for (const std::string& file : stored_files) {
    if (written_files.count(file) != 0) CompareCsv(stored / file, out.path() / file);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, StoredAnswers, ::testing::ValuesIn(ReadCases()),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           std::string name = param.param.name;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

}  // namespace
}  // namespace cosmems::testing
