#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>

#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// One scalar motion of a frame (a point's displacement along a direction) as sparse weights
/// over the reduced degrees of freedom it depends on: at most two carriers' six.
struct DofWeights {
  std::array<int, 12> dof{};  ///< the distinct degrees of freedom it moves with (count of them)
  std::array<double, 12> n{};
  int count = 0;

  /// Sets the weights `w` of the carriers' degrees of freedom `dofs` (-1: anchored), merged by
  /// dof (an element whose ends share a body), the rotation's round-off (below 1e-12 of the
  /// largest) left out, as it is from the model's band.
  void Set(const std::array<int, 12>& dofs, const Eigen::Matrix<double, 12, 1>& w) {
    count = 0;
    const double largest = w.cwiseAbs().maxCoeff();
    for (int a = 0; a < 12; ++a) {
      if (dofs[a] < 0 || std::abs(w[a]) <= 1e-12 * largest) continue;
      int* end = dof.data() + count;
      int* at = std::find(dof.data(), end, dofs[a]);
      if (at == end) {
        dof[count] = dofs[a];
        n[count++] = w[a];
      } else {
        n[at - dof.data()] += w[a];
      }
    }
  }

  /// The motion for the vector x (a displacement or a velocity), in x's units.
  double Dot(const Eigen::VectorXd& x) const {
    double u = 0.0;
    for (int i = 0; i < count; ++i) u += n[i] * x[dof[i]];
    return u;
  }
  /// w^T A w, the dofs within A's band of each other (a matrix the weights' own stiffness
  /// k w w^T is added to has room for them): the compliance along the motion for A = K^-1's band
  /// (BandCholesky::InverseWithinBand).
  double QuadraticForm(const SymmetricBandMatrix& a) const {
    double sum = 0.0;
    for (int i = 0; i < count; ++i) {
      double row = 0.0;
      for (int j = 0; j < count; ++j) row += a(dof[i], dof[j]) * n[j];
      sum += n[i] * row;
    }
    return sum;
  }
};

}  // namespace cosmems
