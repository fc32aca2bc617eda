#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/element_interpolation.hpp"

namespace cosmems {

/// uy at a point of the beam as a linear functional of the reduced displacement: the Hermite
/// weights of the element holding the point, so recording it costs O(1) per sample.
struct OutputPoint {
  std::vector<std::pair<int, double>> weights;  ///< (reduced index, weight), internal units
  double length_unit = 1.0;

  template <int Dim>
  static OutputPoint DeflectionAt(const BeamModel<Dim>& model, double x) {
    OutputPoint out;
    out.length_unit = model.units().length;
    const auto [e, xi] = model.Locate(x / model.units().length);
    const double l = model.elements()[e].properties().length;
    const ShapeValues s = ShapeValues::At(model.bases(), xi);
    const double w[4] = {s.bending[0], l * s.bending[1], s.bending[2], l * s.bending[3]};
    const NodalDof dof[4] = {NodalDof::kUy, NodalDof::kRz, NodalDof::kUy, NodalDof::kRz};
    for (int a = 0; a < 4; ++a) {
      const int r = model.dofs().Reduced(e + a / 2, dof[a]);
      if (r >= 0 && w[a] != 0.0) out.weights.emplace_back(r, w[a]);
    }
    return out;
  }

  /// uy [m] from a reduced displacement vector.
  double Evaluate(const Eigen::VectorXd& d) const {
    double sum = 0.0;
    for (const auto& [r, w] : weights) sum += w * d[r];
    return sum * length_unit;
  }

  /// The same functional applied to the columns of a matrix (e.g. mode shapes).
  Eigen::RowVectorXd Evaluate(const Eigen::MatrixXd& columns) const {
    Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(columns.cols());
    for (const auto& [r, w] : weights) sum += w * columns.row(r);
    return sum * length_unit;
  }
};

}  // namespace cosmems
