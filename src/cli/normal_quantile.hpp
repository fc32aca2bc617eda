#pragma once

namespace cosmems::internal {

/// The standard normal distribution's CDF, Phi(x) = erfc(-x / sqrt 2) / 2.
double NormalCdf(double x);

/// Phi's inverse on (0, 1), to a few units of the last place: the rational approximation of
/// Abramowitz & Stegun 26.2.23 (error below 4.5e-4) refined by Halley steps on Phi itself. Throws
/// std::invalid_argument outside (0, 1).
double NormalQuantile(double p);

}  // namespace cosmems::internal
