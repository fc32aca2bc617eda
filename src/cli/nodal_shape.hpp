#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/analysis/beam_field.hpp"

namespace cosmems::internal {

/// Nodal values (one row per node: ux, uy, uz, rx, ry, rz in SI) with the node's x [m] in front,
/// as the CSV files list them; `node_x` in internal units of `length_unit` metres.
inline Eigen::MatrixXd WithNodePositions(const std::vector<double>& node_x, double length_unit,
                                         const Eigen::MatrixXd& values) {
  Eigen::MatrixXd out(values.rows(), 7);
  for (Eigen::Index n = 0; n < values.rows(); ++n) out(n, 0) = node_x[n] * length_unit;
  out.rightCols<6>() = values;
  return out;
}

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
  return WithNodePositions(model.NodeX(), model.units().length,
                           scale > 0.0 ? Eigen::MatrixXd(values / scale) : values);
}

}  // namespace cosmems::internal
