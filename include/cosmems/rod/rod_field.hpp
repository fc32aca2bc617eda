#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "cosmems/rod/cosserat_rod.hpp"
#include "cosmems/rod/rod_state.hpp"
#include "cosmems/rod/so3.hpp"

namespace cosmems {

/// What a Cosserat rod's state means in SI, as BeamField does for the linear beam: nodal
/// displacements and rotation vectors, the largest deflection toward the substrate and the
/// largest stress. The rod and the state must outlive it.
class RodField {
 public:
  RodField(const CosseratRod& rod, const RodState& state) : rod_(rod), state_(state) {}

  /// One row per node: (ux, uy, uz) [m], then the rotation vector (rx, ry, rz) [rad] lifted
  /// continuously from the first node as CosseratRod::TipRotation does, so its last row ends
  /// with the tip rotation.
  Eigen::MatrixXd AtNodes() const {
    Eigen::MatrixXd out(rod_.NodeCount(), 6);
    Eigen::Vector3d theta = QuaternionLog(state_.Rotation(0));
    for (int i = 0; i < rod_.NodeCount(); ++i) {
      if (i > 0) theta = RotationVectorNear(state_.Rotation(i), theta);
      out.row(i).head<3>() = rod_.units().length * state_.displacement.col(i).transpose();
      out.row(i).tail<3>() = theta.transpose();
    }
    return out;
  }

  /// The largest displacement toward the substrate (-y) of any node [m]; 0 when none moves
  /// that way. The elements are straight between their nodes, so no point lies further.
  double MaxDeflectionTowardSubstrate() const {
    const double most = -state_.displacement.row(1).minCoeff();
    return std::max(0.0, most) * rod_.units().length;
  }

  /// The largest normal stress [Pa] of any element: |N| / A + |M3| (t / 2) / I_z +
  /// |M2| (w / 2) / I_y at a corner of the section, from the element's resultants (constant
  /// along a two-node element); shear and torsion stresses are not included, as in BeamField.
  double MaxStress() const {
    double most = 0.0;
    Eigen::Vector3d force, moment;
    for (int e = 0; e < rod_.ElementCount(); ++e) {
      rod_.ElementResultants(state_, e, force, moment);
      const RectangularSection& s = rod_.description().elements[e].section;
      const double stress = std::abs(force.x()) / s.Area() +
                            std::abs(moment.z()) * 0.5 * s.thickness / s.SecondMomentZ() +
                            std::abs(moment.y()) * 0.5 * s.width / s.SecondMomentY();
      most = std::max(most, stress);
    }
    return most;
  }

 private:
  const CosseratRod& rod_;
  const RodState& state_;
};

}  // namespace cosmems
