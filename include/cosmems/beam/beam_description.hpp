#pragma once

#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/beam/element_spec.hpp"
#include "cosmems/beam/support.hpp"

namespace cosmems {

/// A straight beam as a chain of elements along x, in SI, with a support at every node.
struct BeamDescription {
  std::vector<ElementSpec> elements;
  std::vector<Support> supports;  ///< one per node: elements.size() + 1
  int series_order = 1;           ///< power-series terms: 0 = Hermite + consistent mass
  /// N, the residual axial force in the straight beam (tension > 0), e.g. from fabrication
  /// stress: it enters every analysis through the geometric stiffness.
  double axial_load = 0.0;

  int NodeCount() const { return static_cast<int>(elements.size()) + 1; }

  double Length() const {
    return std::accumulate(elements.begin(), elements.end(), 0.0,
                           [](double sum, const ElementSpec& e) { return sum + e.length; });
  }

  /// The internal units of a model of this beam: the whole length, the first element's E I_z
  /// and rho A (UnitSystem::ForBeam).
  UnitSystem InternalUnits() const {
    const ElementSpec& first = elements.front();
    return UnitSystem::ForBeam(Length(),
                               first.material.young_modulus * first.section.SecondMomentZ(),
                               first.material.density * first.section.Area());
  }

  /// Throws std::invalid_argument naming the offending field and value.
  void Validate() const {
    if (elements.empty()) throw std::invalid_argument("model.elements = 0: must be at least 1");
    for (std::size_t e = 0; e < elements.size(); ++e) {
      elements[e].Validate("elements[" + std::to_string(e) + "]");
    }
    if (supports.size() != elements.size() + 1) {
      throw std::invalid_argument("supports: " + std::to_string(supports.size()) +
                                  " given, one per node (" + std::to_string(NodeCount()) +
                                  ") needed");
    }
    RequireFinite("structure.axial_load", axial_load);
    if (series_order < 0) {
      throw std::invalid_argument("model.series_order = " + std::to_string(series_order) +
                                  ": must be >= 0");
    }
  }
};

/// A prismatic beam of `elements` equal elements, free everywhere until supports are set.
inline BeamDescription UniformBeam(double length, const Material& material,
                                   const RectangularSection& section, int elements,
                                   int series_order) {
  if (elements < 1) {
    throw std::invalid_argument("model.elements = " + std::to_string(elements) +
                                ": must be at least 1");
  }
  RequirePositive("structure.length", length);
  BeamDescription beam;
  beam.elements.assign(elements, ElementSpec{length / elements, material, section});
  beam.supports.assign(elements + 1, Support::kFree);
  beam.series_order = series_order;
  return beam;
}

/// The structures a scene names: "cantilever" (clamped at x = 0), "bridge" (clamped-clamped),
/// and the devices, netlists of members and bodies (StructureDescription), no one beam: "frame"
/// (the netlist written out) and the parametric devices, whose generators make one:
/// "folded_flexure", "crab_leg", "serpentine", "torsional_micromirror" and "accelerometer".
enum class StructureKind {
  kCantilever,
  kBridge,
  kFrame,
  kFoldedFlexure,
  kCrabLeg,
  kSerpentine,
  kTorsionalMicromirror,
  kAccelerometer,
};

/// Whether the structure is a device (a netlist), not one beam.
constexpr bool IsDevice(StructureKind kind) {
  return kind != StructureKind::kCantilever && kind != StructureKind::kBridge;
}

/// The cantilever or the bridge as a chain of equal elements; a device is refused.
inline BeamDescription MakeStructure(StructureKind kind, double length, const Material& material,
                                     const RectangularSection& section, int elements,
                                     int series_order) {
  if (IsDevice(kind)) throw std::invalid_argument("structure.kind: a device, not one beam");
  BeamDescription beam = UniformBeam(length, material, section, elements, series_order);
  beam.supports.front() = Support::kClamped;
  if (kind == StructureKind::kBridge) beam.supports.back() = Support::kClamped;
  return beam;
}

}  // namespace cosmems
