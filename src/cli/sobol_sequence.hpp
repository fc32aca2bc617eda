#pragma once

#include <cstdint>
#include <vector>

namespace cosmems::internal {

/// The Sobol low-discrepancy sequence in up to kMaxDimensions dimensions, with Joe & Kuo's
/// direction numbers (new-joe-kuo-6.21201; Joe & Kuo, SIAM J. Sci. Comput. 30, 2008), 32 bits a
/// coordinate. Point i is computed directly from i (not by Gray-code recurrence), so any
/// worker can draw any point.
class SobolSequence {
 public:
  static constexpr int kMaxDimensions = 16;

  /// Throws std::invalid_argument for a dimension count outside [1, kMaxDimensions].
  explicit SobolSequence(int dimensions);

  int dimensions() const { return static_cast<int>(directions_.size()); }
  /// Coordinate j of point `index`, in [0, 1), XORed with `shift` (a random digital shift keeps
  /// the sequence's stratification and moves its points off the grid's corners).
  double Coordinate(std::uint64_t index, int j, std::uint32_t shift = 0) const;

 private:
  std::vector<std::vector<std::uint32_t>> directions_;  ///< v_{j,k} << (32 - k), k = 1..32
};

}  // namespace cosmems::internal
