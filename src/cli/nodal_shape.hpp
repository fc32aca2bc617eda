#pragma once

#include <Eigen/Core>
#include <vector>

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

}  // namespace cosmems::internal
