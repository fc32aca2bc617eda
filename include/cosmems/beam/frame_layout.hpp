#pragma once

#include <array>

namespace cosmems {

/// The six nodal degrees of freedom of a 3-D frame node, in this order.
enum class NodalDof { kUx = 0, kUy = 1, kUz = 2, kRx = 3, kRy = 4, kRz = 5 };

/// The four fields of a straight frame: axial (ux), bending toward the substrate (uy, rz),
/// bending across the width (uz, ry) and torsion (rx). A linear straight beam of doubly
/// symmetric section never couples one field to another.
enum class DofField { kAxial = 0, kBendingY = 1, kBendingZ = 2, kTorsion = 3 };
inline constexpr int kFieldCount = 4;

/// The field a nodal degree of freedom belongs to.
constexpr DofField FieldOf(NodalDof dof) {
  constexpr std::array<DofField, 6> kField = {DofField::kAxial,    DofField::kBendingY,
                                              DofField::kBendingZ, DofField::kTorsion,
                                              DofField::kBendingZ, DofField::kBendingY};
  return kField[static_cast<int>(dof)];
}

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
  /// The NodalDof at each position of the node's block (the inverse of kIndex).
  static constexpr std::array<NodalDof, kNodeDofs> kDof = {
      NodalDof::kUx, NodalDof::kUy, NodalDof::kUz, NodalDof::kRx, NodalDof::kRy, NodalDof::kRz};
};

template <>
struct FrameLayout<2> {
  static constexpr int kNodeDofs = 3;
  static constexpr std::array<int, 6> kIndex = {0, 1, -1, -1, -1, 2};
  static constexpr std::array<NodalDof, kNodeDofs> kDof = {NodalDof::kUx, NodalDof::kUy,
                                                           NodalDof::kRz};
};

}  // namespace cosmems
