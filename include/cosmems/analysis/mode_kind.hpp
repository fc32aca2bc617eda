#pragma once

#include <Eigen/Core>
#include <array>

#include "cosmems/beam/beam_model.hpp"

namespace cosmems {

/// What a vibration mode mostly is, by where its kinetic energy sits.
enum class ModeKind { kBendingY, kBendingZ, kTorsion, kAxial };

/// The JSON spelling: "bending_y" | "bending_z" | "torsion" | "axial".
constexpr const char* ToString(ModeKind kind) {
  switch (kind) {
    case ModeKind::kBendingY:
      return "bending_y";
    case ModeKind::kBendingZ:
      return "bending_z";
    case ModeKind::kTorsion:
      return "torsion";
    case ModeKind::kAxial:
      return "axial";
  }
  return "unknown";
}

/// Classifies a mode shape (reduced, internal units) by the share of x^T M_0 x carried by each
/// group of degrees of freedom: ux axial; uy, rz bending toward the substrate; uz, ry bending
/// across the width; rx torsion. The groups are uncoupled in a straight beam, so each mode
/// lives almost entirely in one of them.
template <int Dim>
ModeKind ClassifyMode(const BeamModel<Dim>& model, const Eigen::VectorXd& shape) {
  constexpr std::array<ModeKind, 6> kGroup = {ModeKind::kAxial,    ModeKind::kBendingY,
                                              ModeKind::kBendingZ, ModeKind::kTorsion,
                                              ModeKind::kBendingZ, ModeKind::kBendingY};
  std::array<double, 4> energy{};
  for (int group = 0; group < 4; ++group) {
    Eigen::VectorXd part = Eigen::VectorXd::Zero(shape.size());
    for (int node = 0; node < model.NodeCount(); ++node) {
      for (int d = 0; d < 6; ++d) {
        const int r = model.dofs().Reduced(node, static_cast<NodalDof>(d));
        if (r >= 0 && static_cast<int>(kGroup[d]) == group) part[r] = shape[r];
      }
    }
    energy[group] = part.dot(model.Mass(0) * part);
  }
  int best = 0;
  for (int group = 1; group < 4; ++group) {
    if (energy[group] > energy[best]) best = group;
  }
  return static_cast<ModeKind>(best);
}

}  // namespace cosmems
