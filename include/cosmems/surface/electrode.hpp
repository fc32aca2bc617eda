#pragma once

#include <algorithm>
#include <array>
#include <limits>

namespace cosmems {

/// A parallel-plate electrode on the substrate: the rectangle x in [x[0], x[1]], z in [z[0], z[1]]
/// [m] of the substrate plane, in the structure's coordinates. The default covers the whole plane
/// (an electrode under all of the structure).
struct Electrode {
  static constexpr double kUnbounded = std::numeric_limits<double>::infinity();
  std::array<double, 2> x = {-kUnbounded, kUnbounded};
  std::array<double, 2> z = {-kUnbounded, kUnbounded};

  /// The part of [a[0], a[1]] x [b[0], b[1]] (x by z) over the electrode; empty when either side
  /// of it is not positive.
  std::array<std::array<double, 2>, 2> Clip(const std::array<double, 2>& a,
                                            const std::array<double, 2>& b) const {
    return {{{std::max(a[0], x[0]), std::min(a[1], x[1])},
             {std::max(b[0], z[0]), std::min(b[1], z[1])}}};
  }
};

}  // namespace cosmems
