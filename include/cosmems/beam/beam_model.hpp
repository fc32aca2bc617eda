#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "cosmems/beam/beam_description.hpp"
#include "cosmems/beam/dof_map.hpp"
#include "cosmems/beam/frame_element.hpp"
#include "cosmems/core/units.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// The assembled, constant data of a linear beam: internal units, elements, the free-DOF map,
/// and the global K_L and mass terms M_0, M_2, ... in band storage (Model of the Model/Data
/// split: built once, read by every solver and step).
///
/// Dim = 2 is the planar frame (ux, uy, rz); Dim = 3 the full frame. Supported degrees of
/// freedom are removed, not penalised, so every matrix is exactly the free-free block.
template <int Dim>
class BeamModel {
 public:
  static constexpr int kNodeDofs = FrameLayout<Dim>::kNodeDofs;
  using Element = FrameElement<Dim>;

  explicit BeamModel(const BeamDescription& description)
      : description_((description.Validate(), description)),
        units_(UnitsFor(description)),
        bases_(description.series_order),
        dofs_(description.supports) {
    double x = 0.0;
    node_x_.push_back(0.0);
    for (const ElementSpec& spec : description.elements) {
      elements_.emplace_back(ElementProperties::From(spec, units_));
      x += elements_.back().properties().length;
      node_x_.push_back(x);
    }
    const int bandwidth = Bandwidth();
    stiffness_ = SymmetricBandMatrix(dofs_.size(), bandwidth);
    mass_.assign(bases_.order() + 1, SymmetricBandMatrix(dofs_.size(), bandwidth));
    for (int e = 0; e < ElementCount(); ++e) {
      Scatter(e, elements_[e].Stiffness(bases_), stiffness_);
      for (int j = 0; j <= bases_.order(); ++j) Scatter(e, elements_[e].Mass(bases_, j), mass_[j]);
    }
  }

  const BeamDescription& description() const { return description_; }
  const UnitSystem& units() const { return units_; }
  const FrameBases& bases() const { return bases_; }
  const DofMap<Dim>& dofs() const { return dofs_; }
  const std::vector<Element>& elements() const { return elements_; }

  int ElementCount() const { return static_cast<int>(elements_.size()); }
  int NodeCount() const { return ElementCount() + 1; }
  int FreeDofCount() const { return dofs_.size(); }
  int SeriesOrder() const { return bases_.order(); }
  /// Node positions along x in internal units (0 ... 1 for the whole beam).
  const std::vector<double>& NodeX() const { return node_x_; }

  /// K_L (internal units).
  const SymmetricBandMatrix& Stiffness() const { return stiffness_; }
  /// M_{2j}, j = 0 ... SeriesOrder() (internal units).
  const SymmetricBandMatrix& Mass(int j) const { return mass_.at(j); }

  /// The element holding x (internal units) and the local coordinate xi in [0, 1] there.
  std::pair<int, double> Locate(double x) const {
    const auto it = std::upper_bound(node_x_.begin(), node_x_.end(), x);
    int e = static_cast<int>(it - node_x_.begin()) - 1;
    e = std::clamp(e, 0, ElementCount() - 1);
    const double xi = (x - node_x_[e]) / elements_[e].properties().length;
    return {e, std::clamp(xi, 0.0, 1.0)};
  }

  /// Reduced index of the element's local degree of freedom a (0 ... 2 kNodeDofs - 1), or -1.
  int ElementDof(int element, int a) const {
    return dofs_.Reduced(element + a / kNodeDofs, a % kNodeDofs);
  }

 private:
  // Units from the first element: the whole beam's length, that element's E I_z and rho A.
  static UnitSystem UnitsFor(const BeamDescription& d) {
    const ElementSpec& first = d.elements.front();
    return UnitSystem::ForBeam(d.Length(),
                               first.material.young_modulus * first.section.SecondMomentZ(),
                               first.material.density * first.section.Area());
  }

  int Bandwidth() const {
    int bandwidth = 0;
    for (int e = 0; e < ElementCount(); ++e) {
      int lo = dofs_.size();
      int hi = -1;
      for (int a = 0; a < Element::kDofs; ++a) {
        const int r = ElementDof(e, a);
        if (r < 0) continue;
        lo = std::min(lo, r);
        hi = std::max(hi, r);
      }
      bandwidth = std::max(bandwidth, hi - lo);
    }
    return bandwidth;
  }

  void Scatter(int e, const typename Element::Matrix& local, SymmetricBandMatrix& global) const {
    for (int b = 0; b < Element::kDofs; ++b) {
      const int rb = ElementDof(e, b);
      if (rb < 0) continue;
      for (int a = b; a < Element::kDofs; ++a) {
        const int ra = ElementDof(e, a);
        if (ra < 0) continue;
        global.Add(ra, rb, local(a, b));  // a >= b: each pair once
      }
    }
  }

  BeamDescription description_;
  UnitSystem units_;
  FrameBases bases_;
  DofMap<Dim> dofs_;
  std::vector<Element> elements_;
  std::vector<double> node_x_;
  SymmetricBandMatrix stiffness_;
  std::vector<SymmetricBandMatrix> mass_;
};

}  // namespace cosmems
