#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sobol_sequence.hpp"
#include "sweep_parameter.hpp"

namespace cosmems::internal {

/// The most samples a sweep may have (grid points x draws): ten times the largest yield study
/// doc/sweeps.md plans for (10^6). Rank 0 keeps every row in memory for the summary, a few
/// kilobytes each.
constexpr std::int64_t kMaxSweepSamples = 10'000'000;

/// How a sweep draws its random parameters.
enum class SweepMethod { kMonteCarlo, kLatinHypercube, kSobol };
/// "monte-carlo", "lhs", "sobol"
const char* ToString(SweepMethod method);
/// Throws CliInputError naming `option` for a name that is none of them.
SweepMethod ParseSweepMethod(const std::string& name, const std::string& option);

/// The samples of a sweep, each a function of its index alone: the full grid of the grid
/// parameters, and at each grid point `draws` draws of the random ones (1 without any). Sample
/// i is grid point i / draws (the last grid parameter varying fastest) and draw i % draws.
///
/// - Monte Carlo: each sample's numbers come from its own stream, seeded by mixing the sweep's
///   seed with the sample's index (SplitMix64), so a sample's values do not depend on who ran it.
/// - Latin hypercube: draw k lies in stratum pi_j(k) of [0, 1) along each random parameter j,
///   pi_j a permutation drawn from the sweep's seed, its place within the stratum from the
///   sample's stream.
/// - Sobol: draw k is point k of the Sobol sequence, digitally shifted by the sweep's seed.
/// LHS and Sobol give every grid point the same design (common random numbers).
class SweepPlan {
 public:
  /// Throws CliInputError for draws below 1, a Sobol sweep of more random parameters than the
  /// sequence has dimensions, or more samples than kMaxSweepSamples (checked before anything
  /// of the samples' size is allocated).
  SweepPlan(std::vector<SweepParameter> parameters, SweepMethod method, std::int64_t draws,
            std::uint64_t seed);

  const std::vector<SweepParameter>& parameters() const { return parameters_; }
  SweepMethod method() const { return method_; }
  std::int64_t draws() const { return draws_; }
  std::uint64_t seed() const { return seed_; }
  std::int64_t Count() const { return grid_points_ * draws_; }
  /// Sample `index`'s value of each parameter, in the parameters' order.
  std::vector<nlohmann::json> Values(std::int64_t index) const;

 private:
  std::vector<SweepParameter> parameters_;
  std::vector<int> random_;  ///< the random parameters' positions in parameters_
  SweepMethod method_;
  std::int64_t draws_;
  std::uint64_t seed_;
  std::int64_t grid_points_ = 1;
  std::vector<std::vector<std::int64_t>> strata_;  ///< LHS: pi_j, one per random parameter
  std::vector<std::uint32_t> shifts_;              ///< Sobol: the digital shift of each
  std::optional<SobolSequence> sobol_;
};

/// SplitMix64's output function: a well-mixed 64-bit value of x (Steele, Lea & Flood 2014).
std::uint64_t Mix64(std::uint64_t x);

}  // namespace cosmems::internal
