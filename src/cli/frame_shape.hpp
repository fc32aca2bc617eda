#pragma once

#include <Eigen/Core>

#include "cosmems/structure/frame_model.hpp"

namespace cosmems::internal {

/// A mode or buckling shape (reduced, internal units) at every node, then every body's centre, in
/// SI (ux, uy, uz, rx, ry, rz): scaled so that the largest |translation| is 1, or the largest
/// |rotation| for a shape that barely translates (a solver's normalisation means nothing on a
/// plot).
inline Eigen::MatrixXd FrameShape(const FrameModel& model, const Eigen::VectorXd& shape) {
  const int nodes = static_cast<int>(model.description().nodes.size());
  const int bodies = static_cast<int>(model.mesh().body_carrier.size());
  Eigen::MatrixXd values(nodes + bodies, 6);
  for (int n = 0; n < nodes; ++n) values.row(n) = model.NodeMotion(shape, n).transpose();
  for (int b = 0; b < bodies; ++b) {
    values.row(nodes + b) = model.CarrierMotion(shape, model.mesh().body_carrier[b]).transpose();
  }
  values.leftCols<3>() *= model.units().length;
  double scale = values.leftCols<3>().cwiseAbs().maxCoeff();
  if (!(scale > 1e-6 * values.rightCols<3>().cwiseAbs().maxCoeff() * model.units().length)) {
    scale = values.rightCols<3>().cwiseAbs().maxCoeff();
  }
  return scale > 0.0 ? Eigen::MatrixXd(values / scale) : values;
}

}  // namespace cosmems::internal
