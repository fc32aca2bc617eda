#pragma once

#include <array>

namespace cosmems {

/// The six nodal degrees of freedom of a 3-D frame node, in this order.
enum class NodalDof { kUx = 0, kUy = 1, kUz = 2, kRx = 3, kRy = 4, kRz = 5 };

/// Which nodal degrees of freedom a model of dimension Dim carries, and where.
///
/// Dim = 3: all six. Dim = 2: the planar frame (ux, uy, rz): axial motion and bending toward the
/// substrate, so a planar model never pays for the other plane, torsion or their storage.
template <int Dim>
struct FrameLayout;

template <>
struct FrameLayout<3> {
  static constexpr int kNodeDofs = 6;
  /// Position of each NodalDof in the node's block, or -1 when absent.
  static constexpr std::array<int, 6> kIndex = {0, 1, 2, 3, 4, 5};
};

template <>
struct FrameLayout<2> {
  static constexpr int kNodeDofs = 3;
  static constexpr std::array<int, 6> kIndex = {0, 1, -1, -1, -1, 2};
};

}  // namespace cosmems
