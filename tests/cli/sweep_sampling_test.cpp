// The sweep's sampling: the normal quantile, the Sobol sequence, the plan's grids and draws
// against their distributions' moments, and the parts of a spec.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "cli_errors.hpp"
#include "normal_quantile.hpp"
#include "sobol_sequence.hpp"
#include "sweep_condition.hpp"
#include "sweep_parameter.hpp"
#include "sweep_plan.hpp"
#include "sweep_summary.hpp"

namespace cosmems::internal {
namespace sweep_sampling_test {

constexpr double kPi = 3.14159265358979323846;

TEST(NormalQuantileTest, MatchesTabulatedQuantilesAndInvertsTheCdf) {
  // Tabulated to 16 digits (e.g. Abramowitz & Stegun 26.2; 1.959963984540054 for 97.5 %).
  EXPECT_NEAR(NormalQuantile(0.975), 1.959963984540054, 1e-14);
  EXPECT_NEAR(NormalQuantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(NormalQuantile(0.8413447460685429), 1.0, 1e-13);
  EXPECT_NEAR(NormalQuantile(1e-10), -6.361340902404056, 1e-12);
  // Phi(Phi^-1(p)) = p to round-off relative to the tail probability, from 1e-300. The upper
  // tail by symmetry, as far as 1 - p is not 1: the rounding of 1 - p (u = 1.1e-16) moves the
  // quantile x by u / phi(x), the tolerance below with a factor 4.
  for (double p = 1e-300; p < 0.5; p *= 7.0) {
    const double x = NormalQuantile(p);
    EXPECT_NEAR(NormalCdf(x) / p, 1.0, 1e-12) << p;
    if (p > 1e-15) {
      const double density = std::exp(-0.5 * x * x) / std::sqrt(2.0 * kPi);
      EXPECT_NEAR(NormalQuantile(1.0 - p), -x, 1e-14 + 4.0 * 1.1e-16 / density) << p;
    }
  }
  EXPECT_THROW(NormalQuantile(0.0), std::invalid_argument);
  EXPECT_THROW(NormalQuantile(1.0), std::invalid_argument);
}

TEST(SobolSequenceTest, StartsAsTheKnownSequence) {
  const SobolSequence s(2);
  const double x[4] = {0.0, 0.5, 0.75, 0.25}, y[4] = {0.0, 0.5, 0.25, 0.75};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(s.Coordinate(i, 0), x[i]) << i;
    EXPECT_EQ(s.Coordinate(i, 1), y[i]) << i;
  }
}

// Each of the 2^m equal intervals holds exactly one of the first 2^m points, in every dimension,
// shifted or not: the property that makes a Sobol sample stratified.
TEST(SobolSequenceTest, EveryDimensionIsStratified) {
  const SobolSequence s(SobolSequence::kMaxDimensions);
  for (int m = 1; m <= 10; ++m) {
    const int n = 1 << m;
    for (int j = 0; j < s.dimensions(); ++j) {
      for (const std::uint32_t shift : {0u, 0x9e3779b9u}) {
        std::set<int> cells;
        for (int i = 0; i < n; ++i) cells.insert(static_cast<int>(s.Coordinate(i, j, shift) * n));
        EXPECT_EQ(static_cast<int>(cells.size()), n) << "m " << m << " dimension " << j;
      }
    }
  }
}

// Dimensions 1 and 2 form a (0, m, 2)-net: every box 2^-a by 2^-(m-a) holds one point.
TEST(SobolSequenceTest, TheFirstTwoDimensionsFormANet) {
  const SobolSequence s(2);
  const int m = 8, n = 1 << m;
  for (int a = 0; a <= m; ++a) {
    std::set<std::pair<int, int>> boxes;
    for (int i = 0; i < n; ++i) {
      boxes.insert({static_cast<int>(s.Coordinate(i, 0) * (1 << a)),
                    static_cast<int>(s.Coordinate(i, 1) * (1 << (m - a)))});
    }
    EXPECT_EQ(static_cast<int>(boxes.size()), n) << a;
  }
  EXPECT_THROW(SobolSequence(SobolSequence::kMaxDimensions + 1), std::invalid_argument);
}

TEST(SweepParameterTest, GridsKeepIntegersAndTheirEnds) {
  const SweepParameter elements("model.elements", "4:16:4");
  ASSERT_EQ(elements.values().size(), 4u);
  EXPECT_TRUE(elements.values()[1].is_number_integer());
  EXPECT_EQ(elements.values()[3].get<int>(), 16);
  const SweepParameter length("structure.length", "100e-6:300e-6:3");
  EXPECT_TRUE(length.values()[1].is_number_float());
  EXPECT_EQ(length.values()[2].get<double>(), 300e-6);
  const SweepParameter gap("structure.gap", "log:1e-6:1e-4:3");
  EXPECT_NEAR(gap.values()[1].get<double>(), 1e-5, 1e-20);
  EXPECT_EQ(gap.values()[2].get<double>(), 1e-4);
  const SweepParameter list("analysis.integrator", "[\"newmark\", \"hht\"]");
  EXPECT_EQ(list.values()[1].get<std::string>(), "hht");
  EXPECT_EQ(TomlLiteral(list.values()[1]), "\"hht\"");
  EXPECT_EQ(TomlLiteral(elements.values()[0]), "4");
  EXPECT_EQ(TomlLiteral(nlohmann::json(2.0)), "2.0");
  EXPECT_EQ(TomlLiteral(nlohmann::json(1e-5)), "1e-05");
  EXPECT_EQ(TomlLiteral(nlohmann::json(0.1)), "0.1");
}

TEST(SweepParameterTest, RefusesMalformedSpecsNamingTheKey) {
  for (const char* spec : {"1:2", "1:2:0", "a:2:3", "log:-1:2:3", "normal:1:0", "normal:1",
                           "uniform:2:1", "lognormal:-1:1", "truncnormal:0:1:2:1",
                           "truncnormal:0:1:50:60", "beta:1:2", "[]", "[{a = 1}]"}) {
    try {
      SweepParameter("structure.length", spec);
      ADD_FAILURE() << spec << " accepted";
    } catch (const CliInputError& e) {
      EXPECT_NE(std::string(e.what()).find("--vary structure.length=" + std::string(spec)),
                std::string::npos)
          << e.what();
    }
  }
}

// Sample i's values depend on i alone: the same from a fresh plan, in any order.
TEST(SweepPlanTest, ASampleDependsOnItsIndexAlone) {
  for (const SweepMethod method :
       {SweepMethod::kMonteCarlo, SweepMethod::kLatinHypercube, SweepMethod::kSobol}) {
    auto make = [&] {
      return SweepPlan({SweepParameter("a", "1:3:3"), SweepParameter("b", "normal:0:1"),
                        SweepParameter("c", "uniform:2:5")},
                       method, 16, 42);
    };
    const SweepPlan first = make(), second = make();
    ASSERT_EQ(first.Count(), 48);
    std::vector<std::vector<nlohmann::json>> forward;
    for (std::int64_t i = 0; i < second.Count(); ++i) forward.push_back(second.Values(i));
    for (std::int64_t i = first.Count() - 1; i >= 0; --i) EXPECT_EQ(first.Values(i), forward[i]);
    // Grid point i / 16, the last grid key fastest; every grid point gets the draws.
    EXPECT_EQ(first.Values(0)[0].get<int>(), 1);
    EXPECT_EQ(first.Values(17)[0].get<int>(), 2);
    EXPECT_EQ(first.Values(47)[0].get<int>(), 3);
    EXPECT_NE(SweepPlan(first.parameters(), method, 16, 43).Values(5), first.Values(5));
  }
}

// A sweep has at most kMaxSweepSamples samples, refused before anything of their number is
// allocated: a grid of 10^12 points names the key that took it past the limit.
TEST(SweepPlanTest, TheNumberOfSamplesIsBounded) {
  const SweepParameter a("a", "0:1:1000000"), b("b", "0:1:1000000");
  try {
    (void)SweepPlan({a, b}, SweepMethod::kMonteCarlo, 1, 1);
    ADD_FAILURE() << "a grid of 10^12 points was accepted";
  } catch (const CliInputError& error) {
    EXPECT_NE(std::string(error.what()).find("--vary b: the grid has more than 10000000 points"),
              std::string::npos)
        << error.what();
  }
  // At the limit itself the plan is made.
  EXPECT_EQ(SweepPlan({SweepParameter("a", "0:1:10000"), SweepParameter("b", "0:1:1000")},
                      SweepMethod::kMonteCarlo, 1, 1)
                .Count(),
            10000000);
  EXPECT_THROW(
      SweepPlan({SweepParameter("a", "normal:0:1")}, SweepMethod::kLatinHypercube, 10000001, 1),
      CliInputError);
}

// Each stratum of [0, 1) along each key holds exactly one of the draws.
TEST(SweepPlanTest, LatinHypercubeAndSobolDrawsAreStratified) {
  const int n = 256;
  for (const SweepMethod method : {SweepMethod::kLatinHypercube, SweepMethod::kSobol}) {
    const SweepPlan plan({SweepParameter("a", "uniform:0:1"), SweepParameter("b", "uniform:0:1"),
                          SweepParameter("c", "uniform:0:1")},
                         method, n, 7);
    for (int j = 0; j < 3; ++j) {
      std::set<int> strata;
      for (int i = 0; i < n; ++i)
        strata.insert(static_cast<int>(plan.Values(i)[j].get<double>() * n));
      EXPECT_EQ(static_cast<int>(strata.size()), n) << ToString(method) << " " << j;
    }
  }
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The draws' mean and variance against the distribution's, within four standard errors: the
// sample mean errs by sigma / sqrt(n), the sample variance by about var sqrt((kurtosis - 1) / n).
void ExpectMoments(const std::string& spec, SweepMethod method, double mean, double variance,
                   double kurtosis, double lo = -kInfinity, double hi = kInfinity) {
  const int n = 20000;
  const SweepPlan plan({SweepParameter("x", spec)}, method, n, 2026);
  double sum = 0.0, squares = 0.0;
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) {
    x[i] = plan.Values(i)[0].get<double>();
    sum += x[i];
    ASSERT_GE(x[i], lo);
    ASSERT_LE(x[i], hi);
  }
  const double m = sum / n;
  for (const double xi : x) squares += (xi - m) * (xi - m);
  const double v = squares / (n - 1);
  EXPECT_NEAR(m, mean, 4.0 * std::sqrt(variance / n)) << spec << " " << ToString(method);
  EXPECT_NEAR(v, variance, 4.0 * variance * std::sqrt((kurtosis - 1.0) / n))
      << spec << " " << ToString(method);
}

TEST(SweepPlanTest, DrawsHaveTheirDistributionsMoments) {
  for (const SweepMethod method :
       {SweepMethod::kMonteCarlo, SweepMethod::kLatinHypercube, SweepMethod::kSobol}) {
    ExpectMoments("uniform:2:5", method, 3.5, 9.0 / 12.0, 1.8, 2.0, 5.0);
    ExpectMoments("normal:10:2", method, 10.0, 4.0, 3.0);
    // A log-normal value of mean 2 and standard deviation 0.5: s^2 = ln(1 + 1/16).
    const double s2 = std::log1p(1.0 / 16.0);
    const double kurtosis = std::exp(4 * s2) + 2 * std::exp(3 * s2) + 3 * std::exp(2 * s2) - 3;
    ExpectMoments("lognormal:2:0.5", method, 2.0, 0.25, kurtosis, 0.0);
    // The standard normal truncated to [-1, 2]: mean (phi(a) - phi(b)) / Z, variance
    // 1 + (a phi(a) - b phi(b)) / Z - mean^2.
    auto phi = [](double t) { return std::exp(-0.5 * t * t) / std::sqrt(2.0 * kPi); };
    const double z = NormalCdf(2.0) - NormalCdf(-1.0);
    const double mu = (phi(-1.0) - phi(2.0)) / z;
    const double var = 1.0 + (-1.0 * phi(-1.0) - 2.0 * phi(2.0)) / z - mu * mu;
    ExpectMoments("truncnormal:0:1:-1:2", method, mu, var, 3.0, -1.0, 2.0);
  }
}

TEST(SweepConditionTest, ReadsFieldOperatorAndBound) {
  const nlohmann::ordered_json result = {
      {"pullin_voltage_v", 21.5}, {"stuck", false}, {"frequencies_hz", {70000.0, 430000.0}}};
  EXPECT_TRUE(SweepCondition("pullin_voltage_v>=20").Met(result));
  EXPECT_FALSE(SweepCondition("pullin_voltage_v < 20").Met(result));
  EXPECT_TRUE(SweepCondition("frequencies_hz[0]<75000").Met(result));
  EXPECT_FALSE(SweepCondition("frequencies_hz[1]<75000").Met(result));
  EXPECT_FALSE(SweepCondition("frequencies_hz[2]<75000").Met(result));
  EXPECT_TRUE(SweepCondition("stuck==0").Met(result));
  EXPECT_FALSE(SweepCondition("missing!=0").Met(result));
  for (const char* bad : {"pullin_voltage_v", ">=20", "x>=", "x>=abc", "x=>3"}) {
    EXPECT_THROW(SweepCondition{bad}, CliInputError) << bad;
  }
}

// The summary of 101 samples x = 1..101 (y = 3 + 2x - 5b, b alternating 0 and 1) and one
// failed sample: statistics by hand (variance n (n + 1) / 12 with n = 101, type-7 quantiles
// 1 + p (n - 1)), the yield over all 102 samples, and the exact plane.
TEST(SweepSummaryTest, StatisticsYieldAndSensitivities) {
  std::vector<SweepRow> rows;
  for (int i = 1; i <= 101; ++i) {
    SweepRow row;
    row.index = i;
    row.status = "ok";
    row.parameters = {{"a", i}, {"b", i % 2}, {"name", "same"}};
    row.result = {{"x", static_cast<double>(i)}, {"y", 3.0 + 2.0 * i - 5.0 * (i % 2)}};
    rows.push_back(row);
  }
  SweepRow failed;
  failed.status = "invalid: structure.length = -1";
  failed.parameters = {{"a", 0}, {"b", 0}, {"name", "same"}};
  rows.push_back(failed);
  const nlohmann::ordered_json summary = SummarizeSweep(rows, {SweepCondition("x>=91")});
  EXPECT_EQ(summary["samples"], 102);
  EXPECT_EQ(summary["failed"], 1);
  EXPECT_DOUBLE_EQ(summary["yield"].get<double>(), 11.0 / 102.0);
  const auto& x = summary["outputs"]["x"];
  EXPECT_DOUBLE_EQ(x["mean"].get<double>(), 51.0);
  EXPECT_NEAR(x["std"].get<double>(), std::sqrt(101.0 * 102.0 / 12.0), 1e-12);
  EXPECT_EQ(x["min"].get<double>(), 1.0);
  EXPECT_EQ(x["max"].get<double>(), 101.0);
  const std::pair<const char*, double> quantiles[] = {
      {"p01", 2.0}, {"p05", 6.0}, {"p50", 51.0}, {"p95", 96.0}, {"p99", 100.0}};
  for (const auto& [name, value] : quantiles) {
    EXPECT_NEAR(x["quantiles"][name].get<double>(), value, 1e-12) << name;
  }
  // The plane y = 3 + 2 a - 5 b through the samples that ran; "name" does not vary.
  EXPECT_NEAR(summary["sensitivities"]["y"]["a"].get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(summary["sensitivities"]["y"]["b"].get<double>(), -5.0, 1e-12);
  EXPECT_FALSE(summary["sensitivities"]["y"].contains("name"));
}

}  // namespace sweep_sampling_test
}  // namespace cosmems::internal
