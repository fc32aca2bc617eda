#pragma once

// Shared fixtures of the core tests: the paper's reference silicon beams and the closed-form
// frequency equations of Euler-Bernoulli beams.

#include <cmath>

#include "cosmems/cosmems.hpp"

namespace cosmems::test {

inline Material Silicon() { return Material{169e9, 2330.0, 0.22}; }
inline RectangularSection ReferenceSection() { return RectangularSection{20e-6, 2e-6}; }
inline constexpr double kReferenceLength = 200e-6;
inline constexpr double kReferenceWidth = 20e-6;
inline constexpr double kReferenceThickness = 2e-6;
/// The reference cantilever's gap to the substrate.
inline constexpr double kReferenceGap = 2e-6;
/// A relative tolerance at a few ulps of double's round-off, for results exact in exact arithmetic.
inline constexpr double kRoundOff = 1e-14;

/// The reference section's bending stiffnesses (toward the substrate, across the width) and
/// mass per length, in silicon.
inline double Eiz() { return Silicon().young_modulus * ReferenceSection().SecondMomentZ(); }
inline double Eiy() { return Silicon().young_modulus * ReferenceSection().SecondMomentY(); }
inline double RhoA() { return Silicon().density * ReferenceSection().Area(); }

/// A planar cantilever of the reference section in silicon.
inline BeamModel<2> PlanarCantilever(double length, int elements, int order = 0) {
  return BeamModel<2>(MakeStructure(StructureKind::kCantilever, length, Silicon(),
                                    ReferenceSection(), elements, order));
}

/// A 1 x 1 system (a single-degree-of-freedom oscillator's mass or stiffness) and its vectors.
inline SymmetricBandMatrix Scalar(double value) {
  SymmetricBandMatrix m(1, 0);
  m.Add(0, 0, value);
  return m;
}
inline Eigen::VectorXd Vec(double value) { return Eigen::VectorXd::Constant(1, value); }

/// The n-th positive root (n = 1, 2, ...) of cos x cosh x = sign: sign = -1 for a cantilever,
/// +1 for a clamped-clamped beam. Newton from the asymptotic root (2n - 1) pi / 2 (cantilever)
/// or (2n + 1) pi / 2 (clamped-clamped), which lies within 0.2 % of it.
inline double FrequencyRoot(int n, double sign) {
  double x = (sign < 0 ? 2 * n - 1 : 2 * n + 1) * kPi / 2;
  for (int i = 0; i < 50; ++i) {
    const double f = std::cos(x) * std::cosh(x) - sign;
    const double df = -std::sin(x) * std::cosh(x) + std::cos(x) * std::sinh(x);
    x -= f / df;
  }
  return x;
}

/// f_n = x_n^2 / (2 pi L^2) sqrt(EI / rho A) [Hz].
inline double BendingFrequency(double root, double length, double ei, double rho_a) {
  return root * root / (2 * kPi * length * length) * std::sqrt(ei / rho_a);
}

}  // namespace cosmems::test
