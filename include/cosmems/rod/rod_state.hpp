#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "cosmems/rod/so3.hpp"

namespace cosmems {

/// The configuration of a rod's nodes, in its model's internal units: node i sits at
/// X_i + displacement.col(i), X_i its undeformed position on the x axis, and carries the
/// director frame d_k = R_i e_k with R_i = R(q_i) (d1 the axis, d2 toward the substrate, d3 across
/// the width; R = I undeformed).
///
/// Displacements rather than positions are the unknowns so that small deflections keep their
/// relative precision: a strain formed from positions of order L would lose the digits of a
/// 1e-6 L deflection to round-off.
struct RodState {
  Eigen::Matrix3Xd displacement;  ///< u_i (internal length units)
  Eigen::Matrix4Xd rotation;      ///< q_i as Eigen's coefficients (x, y, z, w), unit length

  /// The undeformed, straight rod of `nodes` nodes.
  static RodState Undeformed(int nodes) {
    RodState s;
    s.displacement.setZero(3, nodes);
    s.rotation.setZero(4, nodes);
    s.rotation.row(3).setOnes();
    return s;
  }

  int NodeCount() const { return static_cast<int>(displacement.cols()); }

  Eigen::Quaterniond Rotation(int node) const {
    return Eigen::Quaterniond(rotation(3, node), rotation(0, node), rotation(1, node),
                              rotation(2, node));
  }

  /// Moves the state in the exponential chart by an increment (6 per node: du, then the spatial
  /// rotation theta) scaled by `step`: u_i += step du_i, R_i <- exp(step theta_i^) R_i, the chart
  /// in which the rod's tangent is the Hessian. Rotations compose multiplicatively and are
  /// renormalised, so the quaternions stay unit to round-off. (The solvers step with
  /// CosseratRod::Retract, which agrees with this to first order.)
  void Update(const Eigen::Ref<const Eigen::VectorXd>& increment, double step) {
    for (int i = 0; i < NodeCount(); ++i) {
      displacement.col(i) += step * increment.segment<3>(6 * i);
      Eigen::Quaterniond q = QuaternionExp(step * increment.segment<3>(6 * i + 3)) * Rotation(i);
      q.normalize();
      rotation.col(i) = q.coeffs();
    }
  }

  /// A size for relative increment tests: sqrt(sum |u_i|^2 + |2 vec(q_i)|^2), the second term
  /// 2 sin(|theta_i| / 2), which is |theta_i| for small rotations.
  double Size() const {
    return std::sqrt(displacement.squaredNorm() + 4.0 * rotation.topRows<3>().squaredNorm());
  }
};

}  // namespace cosmems
