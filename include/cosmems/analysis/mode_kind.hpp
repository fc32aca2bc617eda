#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>

#include "cosmems/beam/beam_model.hpp"

namespace cosmems {

/// What a vibration mode mostly is: the field that carries most of its kinetic energy.
using ModeKind = DofField;

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
/// field (see DofField). The fields are uncoupled in a straight beam, so each mode lives almost
/// entirely in one of them.
template <int Dim>
ModeKind ClassifyMode(const BeamModel<Dim>& model, const Eigen::VectorXd& shape) {
  std::array<double, kFieldCount> energy{};
  for (int field = 0; field < kFieldCount; ++field) {
    Eigen::VectorXd part = Eigen::VectorXd::Zero(shape.size());
    for (int node = 0; node < model.NodeCount(); ++node) {
      for (int d = 0; d < 6; ++d) {
        const int r = model.dofs().Reduced(node, static_cast<NodalDof>(d));
        if (r >= 0 && static_cast<int>(FieldOf(static_cast<NodalDof>(d))) == field) {
          part[r] = shape[r];
        }
      }
    }
    energy[field] = part.dot(model.Mass(0) * part);
  }
  const auto best = std::max_element(energy.begin(), energy.end()) - energy.begin();
  return static_cast<ModeKind>(best);
}

}  // namespace cosmems
