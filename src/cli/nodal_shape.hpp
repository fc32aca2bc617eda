#pragma once

#include <Eigen/Core>

#include "cosmems/analysis/beam_field.hpp"

namespace cosmems::internal {

/// A mode or buckling shape (reduced, internal units) at the nodes in SI: one row per node with
/// x (m), then ux, uy, uz, rx, ry, rz scaled to a largest |translation| of 1, or the largest
/// |rotation| for a torsion shape (`by_rotation`): a solver's normalisation means nothing on a
/// plot.
template <int Dim>
Eigen::MatrixXd NodalShape(const BeamModel<Dim>& model, const Eigen::VectorXd& shape,
                           bool by_rotation) {
  const Eigen::MatrixXd values = BeamField<Dim>(model, shape).AtNodes();
  const double scale = by_rotation ? values.rightCols<3>().cwiseAbs().maxCoeff()
                                   : values.leftCols<3>().cwiseAbs().maxCoeff();
  Eigen::MatrixXd out(values.rows(), 7);
  for (Eigen::Index n = 0; n < values.rows(); ++n) {
    out(n, 0) = model.NodeX()[n] * model.units().length;
  }
  out.rightCols<6>() = scale > 0.0 ? Eigen::MatrixXd(values / scale) : values;
  return out;
}

}  // namespace cosmems::internal
