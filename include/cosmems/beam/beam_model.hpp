#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <cstdlib>
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

  /// The numbering defaults to field by field, the narrowest band for the linear frame; a
  /// theory that couples the fields asks for kByNode.
  explicit BeamModel(const BeamDescription& description,
                     DofNumbering numbering = DofNumbering::kByField)
      : description_((description.Validate(), description)),
        units_(description.InternalUnits()),
        bases_(description.series_order),
        dofs_(description.supports, numbering) {
    double x = 0.0;
    node_x_.push_back(0.0);
    for (const ElementSpec& spec : description.elements) {
      elements_.emplace_back(ElementProperties::From(spec, units_));
      x += elements_.back().properties().length;
      node_x_.push_back(x);
    }
    const int bandwidth = Bandwidth();
    const int order = bases_.order();
    elastic_stiffness_ = SymmetricBandMatrix(dofs_.size(), bandwidth);
    elastic_mass_.assign(order + 1, SymmetricBandMatrix(dofs_.size(), bandwidth));
    geometric_.assign(order + 1, SymmetricBandMatrix(dofs_.size(), bandwidth));
    for (int e = 0; e < ElementCount(); ++e) {
      Scatter(e, elements_[e].Stiffness(bases_), elastic_stiffness_);
      for (int j = 0; j <= order; ++j) {
        Scatter(e, elements_[e].Mass(bases_, j), elastic_mass_[j]);
        Scatter(e, elements_[e].Geometric(bases_, j), geometric_[j]);
      }
    }
    axial_load_ = description.axial_load / units_.force;
    stiffness_ = Prestressed(elastic_stiffness_, geometric_[0], axial_load_);
    for (int j = 0; j <= order; ++j) {
      mass_.push_back(j < order ? Prestressed(elastic_mass_[j], geometric_[j + 1], -axial_load_)
                                : elastic_mass_[j]);
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

  /// The stiffness about the straight, prestressed beam: K_L + N0 G_0 with N0 the description's
  /// axial_load (internal units). Equal to K_L when there is no axial load.
  const SymmetricBandMatrix& Stiffness() const { return stiffness_; }
  /// The mass terms about the prestressed beam, D(w) = Stiffness() - sum_j w^(2j+2) Mass(j):
  /// M_2j - N0 G_(j+1) for j < SeriesOrder(), M_2j for the last (internal units).
  const SymmetricBandMatrix& Mass(int j) const { return mass_.at(j); }
  /// K_L alone, and M_2j alone (no axial load).
  const SymmetricBandMatrix& ElasticStiffness() const { return elastic_stiffness_; }
  const SymmetricBandMatrix& ElasticMass(int j) const { return elastic_mass_.at(j); }
  /// G_j per unit axial force, j = 0 ... SeriesOrder(); G_0 is K_NL / N (internal units).
  const SymmetricBandMatrix& Geometric(int j) const { return geometric_.at(j); }
  /// N0 in internal units (tension > 0).
  double AxialLoad() const { return axial_load_; }

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
  // Whether the numbering lets local dofs a and b of an element couple: any two node by node,
  // two of the same field field by field.
  bool MayCouple(int a, int b) const {
    return dofs_.numbering() == DofNumbering::kByNode ||
           FieldOf(FrameLayout<Dim>::kDof[a % kNodeDofs]) ==
               FieldOf(FrameLayout<Dim>::kDof[b % kNodeDofs]);
  }

  // The widest distance between two reduced indices that an element may couple.
  int Bandwidth() const {
    int bandwidth = 0;
    for (int e = 0; e < ElementCount(); ++e) {
      for (int a = 0; a < Element::kDofs; ++a) {
        for (int b = 0; b < a; ++b) {
          const int ra = ElementDof(e, a);
          const int rb = ElementDof(e, b);
          if (ra < 0 || rb < 0 || !MayCouple(a, b)) continue;
          bandwidth = std::max(bandwidth, std::abs(ra - rb));
        }
      }
    }
    return bandwidth;
  }

  static SymmetricBandMatrix Prestressed(const SymmetricBandMatrix& a, const SymmetricBandMatrix& g,
                                         double n) {
    SymmetricBandMatrix out = a;
    if (n != 0.0) out.mutable_data() += n * g.data();
    return out;
  }

  void Scatter(int e, const typename Element::Matrix& local, SymmetricBandMatrix& global) const {
    for (int b = 0; b < Element::kDofs; ++b) {
      const int rb = ElementDof(e, b);
      if (rb < 0) continue;
      for (int a = b; a < Element::kDofs; ++a) {
        const int ra = ElementDof(e, a);
        if (ra < 0) continue;
        if (!MayCouple(a, b)) {
          assert(local(a, b) == 0.0 && "an element coupled two fields numbered apart");
          continue;
        }
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
  double axial_load_ = 0.0;
  SymmetricBandMatrix elastic_stiffness_;
  std::vector<SymmetricBandMatrix> elastic_mass_;
  std::vector<SymmetricBandMatrix> geometric_;
  SymmetricBandMatrix stiffness_;
  std::vector<SymmetricBandMatrix> mass_;
};

}  // namespace cosmems
