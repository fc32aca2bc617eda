#pragma once

#include <cstddef>
#include <cstdint>

#include "cosmems/structure/frame_size.hpp"
#include "toml_field_reader.hpp"

namespace cosmems::internal {

// Every bound a scene's values must keep (doc/scenes.md, Limits): beyond it the model would form
// a product of the values that a double cannot hold (zero, subnormal or infinite), or the run
// would exhaust memory or time on what is almost surely a typo.

// Lengths, from a hundredth of an atom to a metre: beyond every microstructure at both ends.
// Within them and the material bounds below, I = b t^3 / 12 >= 8e-50 m^4, EI, rho A and the
// internal units (UnitSystem::ForBeam: force EI / L^2 in [8e-50, 8e35] N, time in [3e-31, 1e15] s)
// are normal doubles, and so is any product of a few of them.
constexpr Bounds kLength{1e-12, 1.0, "m"};
// Lengths that may be 0: the contact's separation, the gas's mean free path.
constexpr Bounds kLengthOrZero{0.0, kLength.upper, "m"};
// A frame's coordinates, about its origin, and a direction's components (any length).
constexpr Bounds kCoordinate{-kLength.upper, kLength.upper, "m"};
constexpr Bounds kDirection{-1.0, 1.0, ""};
// From below the softest gels (~100 Pa) to above diamond (1.2e12 Pa).
constexpr Bounds kYoungModulus{1.0, 1e13, "Pa"};
// From below the lightest aerogels (~0.2 kg/m^3) to above osmium (22,590 kg/m^3).
constexpr Bounds kDensity{0.1, 1e5, "kg/m^3"};
// A hundred tonnes-force, beyond what any beam within the length bounds carries: the deflection
// of the most compliant beam allowed (F L^3 / 3EI < 1e55 in internal units), its square and its
// cube stay finite.
constexpr Bounds kForce{-1e6, 1e6, "N"};
constexpr Bounds kForcePerLength{-1e6, 1e6, "N/m"};
constexpr Bounds kMoment{-1e6, 1e6, "N m"};
// Transient times, from a femtosecond (below any mechanical period) to eleven days: a step in
// internal units stays above 9e-31 and a duration below 3e36. Frequencies: their reciprocals.
constexpr Bounds kTime{1e-15, 1e6, "s"};
constexpr Bounds kFrequency{1e-6, 1e15, "Hz"};
// The scripted stylus records every tick (80 bytes) up front: an hour at the highest rate,
// 2000 Hz, is 7.2e6 ticks or 576 MB. The built-in motions' cycle count (an int, 2 s a cycle) and
// the OpenHaptics session's end on the steady clock stay far inside their types.
constexpr Bounds kHapticDuration{1e-15, 3600.0, "s"};
// Above any MEMS drive and the breakdown of any gap; V^2 and eps0 V^2 / 2 g^2 at the smallest
// gap (4e24 Pa) stay finite.
constexpr Bounds kVoltage{-1e6, 1e6, "V"};
constexpr Bounds kVoltageMax{1e-6, 1e6, "V"};
// Hamaker constants of real media lie in 1e-21 ... 1e-18 J.
constexpr Bounds kHamaker{1e-25, 1e-15, "J"};
// Works of adhesion of solids lie in 0.01 ... a few J/m^2.
constexpr Bounds kAdhesionEnergy{0.0, 1e3, "J/m^2"};
// A thousand times below a beam in a liquid (Q ~ 1) to a thousand times above the best
// resonators (~1e9).
constexpr Bounds kQualityFactor{1e-3, 1e12, ""};
// C = alpha M + beta K: beta = 1 s already damps every mode above 0.32 Hz beyond critical.
constexpr Bounds kRayleighAlpha{0.0, 1e12, "1/s"};
constexpr Bounds kRayleighBeta{0.0, 1.0, "s"};
// From a thousandth of hydrogen's viscosity (9e-6 Pa s) to a thousand times glycerol's (1.4).
constexpr Bounds kViscosity{1e-8, 1e3, "Pa s"};
// The hand-to-micro scales and the stylus coupling: twelve decades either side of 1, far wider
// than any device and structure need (5000, ~1e5 and ~20 N/m for the paper's cantilever); a
// product of a few of them stays finite.
constexpr Bounds kScale{1e-12, 1e12, ""};
constexpr Bounds kStiffness{1e-12, 1e12, "N/m"};

// Guards against a typo such as 20000000 exhausting memory; far beyond any useful mesh of one
// beam (the power-series elements converge with a handful).
constexpr int kMaxElements = 100000;
constexpr int kMaxSeriesOrder = 6;
// A device's model as a whole: its members' elements add up (a parametric device multiplies
// model.elements by its members, a netlist may list any number), and a netlist's band grows with
// its width, so both are bounded on the netlist (FrameSizeOf) before the model is built. 500,000
// elements (about 3 million unknowns) is 500 times the folded flexure of the benchmarks (1000
// elements, 5970 unknowns, 20 MB), 62,500 a beam of its eight.
constexpr std::int64_t kMaxDeviceElements = 500000;
// The peak memory of a run, estimated from the model's size: kBandMatrices matrices of its band
// (K and the mass terms, the analyses' effective matrices, factors and tangents) and
// kElementBytes for each element (its matrices, transforms and forces). It lies above the
// measured peaks of every analysis (static, modal at series order 6, buckling, transient and
// haptic, linear and stretching) of the folded flexure at 10,000 and 50,000 elements and of a
// 40 x 40 grid of members (84,240 unknowns, band 236): the largest, 23 KB an element, is the
// stretching haptic run of the folded flexure (26 KB estimated); a linear model's band is half
// the bound, and its peak about half the estimate.
constexpr double kBandMatrices = 12.0;
constexpr double kElementBytes = 12288.0;
inline double DeviceBytes(const FrameSize& size) {
  const double band =
      8.0 * static_cast<double>(size.unknowns) * static_cast<double>(size.bandwidth + 1);
  return kBandMatrices * band + kElementBytes * static_cast<double>(size.elements);
}
// A workstation's memory: a run that would take more is refused rather than left to exhaust it.
// The same everywhere, so that a scene valid on one machine (one shard of a sweep) is valid on
// all.
constexpr double kMaxDeviceBytes = 16e9;
// A serpentine spring's spans: real ones have a few to a few tens; each adds two members.
constexpr int kMaxTurns = 100;
// A comb drive's movable fingers: real ones have tens to a few hundred.
constexpr int kMaxFingers = 100000;
// analysis.count and model.modes. Where the wanted modes span a quarter of the model or more, the
// modal solver solves the whole problem densely, O(n^3) for each root at series order >= 1:
// 100 modes (up to 400 unknowns) were measured at 10 s at order 6, 200 (600 unknowns) at a
// minute at order 1; otherwise subspace iteration keeps 2 x count vectors of the model's size.
// Design uses the first few dozen modes.
constexpr int kMaxModes = 100;
// Guards against a typo in duration or time_step: a run this long would take hours and keep a
// timing sample (8 bytes) per step.
constexpr double kMaxSteps = 1e8;
// Scene files are a few hundred bytes to a few kilobytes: reading stops past 1 MiB, so that a
// mistaken path (a log, a disk image) is refused rather than read into memory whole.
constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 20;

}  // namespace cosmems::internal
