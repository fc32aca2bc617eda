#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/beam/frame_layout.hpp"
#include "cosmems/beam/support.hpp"

namespace cosmems {

/// How the free degrees of freedom are ordered.
enum class DofNumbering {
  /// Field after field (DofField order), node by node within each: the fields of a linear
  /// straight frame are uncoupled, so the band is that of one field (3 for bending) whatever the
  /// dimension, against 5 (planar) or 11 (spatial) node by node.
  kByField,
  /// Node after node: the narrowest band for theories that couple the fields.
  kByNode,
};

/// Numbers the free degrees of freedom of a chain of nodes so that its matrices keep a narrow
/// band after the supported ones are removed.
template <int Dim>
class DofMap {
 public:
  static constexpr int kNodeDofs = FrameLayout<Dim>::kNodeDofs;

  DofMap() = default;
  DofMap(const std::vector<Support>& supports, DofNumbering numbering)
      : numbering_(numbering), index_(supports.size() * kNodeDofs, -1) {
    const int passes = numbering == DofNumbering::kByField ? kFieldCount : 1;
    for (int pass = 0; pass < passes; ++pass) {
      for (std::size_t node = 0; node < supports.size(); ++node) {
        for (int d = 0; d < 6; ++d) {
          const auto dof = static_cast<NodalDof>(d);
          const int local = FrameLayout<Dim>::kIndex[d];
          if (local < 0 || Fixes(supports[node], dof)) continue;
          if (passes > 1 && static_cast<int>(FieldOf(dof)) != pass) continue;
          index_[node * kNodeDofs + local] = free_++;
        }
      }
    }
  }

  DofNumbering numbering() const { return numbering_; }
  /// Free degrees of freedom.
  int size() const { return free_; }
  /// Reduced index of the node's local degree of freedom, or -1 when it is supported.
  int Reduced(int node, int local) const { return index_[node * kNodeDofs + local]; }
  /// Reduced index of a NodalDof, or -1 when supported or absent from this layout.
  int Reduced(int node, NodalDof dof) const {
    const int local = FrameLayout<Dim>::kIndex[static_cast<int>(dof)];
    return local < 0 ? -1 : Reduced(node, local);
  }

 private:
  DofNumbering numbering_ = DofNumbering::kByField;
  std::vector<int> index_;
  int free_ = 0;
};

}  // namespace cosmems
