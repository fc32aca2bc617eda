#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/beam/frame_layout.hpp"
#include "cosmems/beam/support.hpp"

namespace cosmems {

/// Numbers the free degrees of freedom node by node, so that a chain of elements keeps a
/// narrow band after the supported ones are removed.
template <int Dim>
class DofMap {
 public:
  static constexpr int kNodeDofs = FrameLayout<Dim>::kNodeDofs;

  DofMap() = default;
  explicit DofMap(const std::vector<Support>& supports) : index_(supports.size() * kNodeDofs, -1) {
    for (std::size_t node = 0; node < supports.size(); ++node) {
      for (int d = 0; d < 6; ++d) {
        const int local = FrameLayout<Dim>::kIndex[d];
        if (local < 0 || Fixes(supports[node], static_cast<NodalDof>(d))) continue;
        index_[node * kNodeDofs + local] = free_++;
      }
    }
  }

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
  std::vector<int> index_;
  int free_ = 0;
};

}  // namespace cosmems
