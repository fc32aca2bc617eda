#pragma once

// What the hard-case tests share: the reference cantilever at any mesh, the round-off a solve with
// its stiffness leaves, and the figures a case measures (iterations, cuts, refused steps, energy
// ratios), kept in the test's XML report (--gtest_output=xml:FILE) for the README's table of hard
// cases.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "cosmems/beam/beam_model.hpp"
#include "test_beams.hpp"

namespace cosmems::test {

inline constexpr double kMachineEpsilon = std::numeric_limits<double>::epsilon();

/// The round-off of a solve with the stiffness of n Hermite elements, relative: its condition
/// grows as n^4 (the fourth difference of bending), so eps n^4 bounds what the factorisation
/// leaves (measured between 0.002 and 0.1 of it at 100 and 1000 elements).
inline double StiffnessRoundOff(int elements) { return kMachineEpsilon * std::pow(elements, 4); }

/// The planar reference cantilever of `elements` elements of series order `order`.
inline BeamModel<2> ReferenceCantilever(int elements, int order) {
  return BeamModel<2>(MakeStructure(StructureKind::kCantilever, kReferenceLength, Silicon(),
                                    ReferenceSection(), elements, order));
}

/// Records `value` as the property `key` of the running test, to four significant digits.
inline void RecordFigure(const std::string& key, double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  ::testing::Test::RecordProperty(key, text);
}

}  // namespace cosmems::test
