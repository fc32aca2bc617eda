#include "sweep_plan.hpp"

#include <cmath>
#include <numeric>
#include <utility>

#include "cli_errors.hpp"

namespace cosmems::internal {
namespace {

constexpr std::uint64_t kGolden = 0x9e3779b97f4a7c15ULL;

// A stream of numbers from one seed: SplitMix64's state walks by the golden ratio.
class Stream {
 public:
  explicit Stream(std::uint64_t seed) : state_(seed) {}
  std::uint64_t Next() { return Mix64(state_ += kGolden); }
  /// In (0, 1): 53 random bits, offset by half a unit so that neither end is reached.
  double Uniform() { return (static_cast<double>(Next() >> 11) + 0.5) * 0x1p-53; }
  /// In [0, n): a remainder, whose bias (below n / 2^64) no sweep can see.
  std::int64_t Below(std::int64_t n) {
    return static_cast<std::int64_t>(Next() % static_cast<std::uint64_t>(n));
  }

 private:
  std::uint64_t state_;
};

// The seed of a stream that belongs to (what, index) of the sweep `seed`.
std::uint64_t SeedOf(std::uint64_t seed, std::uint64_t what, std::uint64_t index) {
  return Mix64(Mix64(seed ^ (what * kGolden)) + index);
}
constexpr std::uint64_t kSampleStream = 1, kStrataStream = 2, kShiftStream = 3;

}  // namespace

std::uint64_t Mix64(std::uint64_t x) {
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

const char* ToString(SweepMethod method) {
  switch (method) {
    case SweepMethod::kMonteCarlo:
      return "monte-carlo";
    case SweepMethod::kLatinHypercube:
      return "lhs";
    case SweepMethod::kSobol:
      return "sobol";
  }
  return "?";
}

SweepMethod ParseSweepMethod(const std::string& name, const std::string& option) {
  for (SweepMethod m :
       {SweepMethod::kMonteCarlo, SweepMethod::kLatinHypercube, SweepMethod::kSobol}) {
    if (name == ToString(m)) return m;
  }
  throw CliInputError(option + " = \"" + name + "\": expected monte-carlo, lhs or sobol");
}

SweepPlan::SweepPlan(std::vector<SweepParameter> parameters, SweepMethod method, std::int64_t draws,
                     std::uint64_t seed)
    : parameters_(std::move(parameters)), method_(method), draws_(draws), seed_(seed) {
  for (std::size_t j = 0; j < parameters_.size(); ++j) {
    if (parameters_[j].IsGrid()) {
      grid_points_ *= static_cast<std::int64_t>(parameters_[j].values().size());
      if (grid_points_ > kMaxSweepSamples) {
        throw CliInputError("--vary " + parameters_[j].key() + ": the grid has more than " +
                            std::to_string(kMaxSweepSamples) + " points, the limit of a sweep");
      }
    } else {
      random_.push_back(static_cast<int>(j));
    }
  }
  if (random_.empty()) draws_ = 1;
  if (draws_ < 1)
    throw CliInputError("--samples = " + std::to_string(draws) + ": must be at least 1");
  // Before the strata below, whose size is the draws'. Both factors are at most the limit, so
  // their product cannot overflow.
  if (draws_ > kMaxSweepSamples || grid_points_ * draws_ > kMaxSweepSamples) {
    throw CliInputError("--samples = " + std::to_string(draws) + ": the sweep would have " +
                        (grid_points_ > 1 ? std::to_string(grid_points_) + " grid points x " : "") +
                        std::to_string(draws) + " samples, above the limit of " +
                        std::to_string(kMaxSweepSamples));
  }
  const int dimensions = static_cast<int>(random_.size());
  if (method_ == SweepMethod::kLatinHypercube) {
    for (int j = 0; j < dimensions; ++j) {
      std::vector<std::int64_t> pi(draws_);
      std::iota(pi.begin(), pi.end(), 0);
      Stream stream(SeedOf(seed_, kStrataStream, j));
      for (std::int64_t k = draws_ - 1; k > 0; --k) std::swap(pi[k], pi[stream.Below(k + 1)]);
      strata_.push_back(std::move(pi));
    }
  } else if (method_ == SweepMethod::kSobol && dimensions > 0) {
    if (dimensions > SobolSequence::kMaxDimensions) {
      throw CliInputError("--method = sobol: " + std::to_string(dimensions) +
                          " random parameters, the sequence has " +
                          std::to_string(SobolSequence::kMaxDimensions) + " dimensions");
    }
    sobol_.emplace(dimensions);
    for (int j = 0; j < dimensions; ++j) {
      shifts_.push_back(static_cast<std::uint32_t>(Mix64(SeedOf(seed_, kShiftStream, j)) >> 32));
    }
  }
}

std::vector<nlohmann::json> SweepPlan::Values(std::int64_t index) const {
  std::vector<nlohmann::json> values(parameters_.size());
  std::int64_t grid = index / draws_;
  const std::int64_t draw = index % draws_;
  for (std::size_t j = parameters_.size(); j-- > 0;) {
    if (!parameters_[j].IsGrid()) continue;
    const auto count = static_cast<std::int64_t>(parameters_[j].values().size());
    values[j] = parameters_[j].values()[grid % count];
    grid /= count;
  }
  Stream stream(SeedOf(seed_, kSampleStream, static_cast<std::uint64_t>(index)));
  for (std::size_t r = 0; r < random_.size(); ++r) {
    double u = 0.0;
    switch (method_) {
      case SweepMethod::kMonteCarlo:
        u = stream.Uniform();
        break;
      case SweepMethod::kLatinHypercube:
        u = (static_cast<double>(strata_[r][draw]) + stream.Uniform()) / draws_;
        break;
      case SweepMethod::kSobol:
        // The middle of the point's cell at 2^-32: never 0 or 1.
        u = sobol_->Coordinate(draw, static_cast<int>(r), shifts_[r]) + 0x1p-33;
        break;
    }
    values[random_[r]] = parameters_[random_[r]].Quantile(u);
  }
  return values;
}

}  // namespace cosmems::internal
