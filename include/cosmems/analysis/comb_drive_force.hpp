#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "cosmems/analysis/comb_drive.hpp"
#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// A frame's comb drives as one nonlinear force: each comb pulls its body's centre by the
/// gradient of its co-energy V^2 C(x, y) / 2 (CombDrive::Capacitance), x and y the centre's
/// motion along the comb's direction and across its fingers. With q = N eps0 t, e = overlap + x
/// and the fingers' gaps g - y and g + y,
///   dC/dx = q (1/(g-y) + 1/(g+y)),            dC/dy = q e (1/(g-y)^2 - 1/(g+y)^2),
///   d2C/dxdy = q (1/(g-y)^2 - 1/(g+y)^2),      d2C/dy2 = 2 q e (1/(g-y)^3 + 1/(g+y)^3),
/// d2C/dx2 = 0. Centred (y = 0) this is CombDrive's engagement force along the direction and its
/// negative stiffness across it, so the suspension's side instability is where K + dr/dd stops
/// being positive definite; off centre the fingers pull the body further aside. r = -grad(V^2
/// C / 2) (an internal force), dr/dd = -V^2 hess(C) / 2 on the body's translations. The body's
/// turn in the plane, which tilts the fingers, is left out, as in CombDrive. Evaluate() allocates
/// nothing and returns false where a finger touches its neighbour (|y| >= g) or the fingers
/// disengage (e <= 0): beyond the model.
class CombDriveForce final : public FrameElementForce {
 public:
  /// Throws std::invalid_argument for a comb CombDrive::Validate() refuses or one whose body is
  /// not in `model`.
  CombDriveForce(const FrameModel& model, std::vector<CombDrive> combs)
      : model_(model), combs_(std::move(combs)) {
    ValidateCombDrives(combs_, static_cast<int>(model.description().bodies.size()));
  }

  /// Scales every comb's voltage by `factor` from now on (1 at construction).
  void SetVoltageFactor(double factor) { factor_ = factor; }

  /// Comb c's engagement x and offset y across its fingers [m] at d.
  Eigen::Vector2d Motion(const Eigen::VectorXd& d, int c) const {
    const CombDrive& comb = combs_[c];
    const Eigen::Vector3d u =
        model_.CarrierMotion(d, model_.mesh().body_carrier[comb.body]).head<3>() *
        model_.units().length;
    return {u.dot(comb.Axis()), u.dot(comb.Lateral())};
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const double length_m = model_.units().length;
    const double force_n = model_.units().force;
    for (int c = 0; c < static_cast<int>(combs_.size()); ++c) {
      const CombDrive& comb = combs_[c];
      const Eigen::Vector2d xy = Motion(d, c);
      const double e = comb.overlap + xy[0];
      const double near = comb.gap - xy[1], far = comb.gap + xy[1];
      if (!(e > 0.0) || !(near > 0.0) || !(far > 0.0)) return false;
      const double v = factor_ * comb.voltage;
      const double half_q = 0.5 * v * v * comb.fingers * kVacuumPermittivity * comb.thickness;
      const double gx = comb.Force(v, xy[1]);                                   // N
      const double cross = half_q * (1.0 / (near * near) - 1.0 / (far * far));  // N/m
      const double gy = e * cross;
      const double gyy = 2.0 * half_q * e * (1.0 / (near * near * near) + 1.0 / (far * far * far));
      const Eigen::Vector3d a = comb.Axis(), l = comb.Lateral();
      const Eigen::Vector3d pull = (gx * a + gy * l) / force_n;
      const Eigen::Matrix3d hessian =
          (cross * (a * l.transpose() + l * a.transpose()) + gyy * l * l.transpose()) *
          (length_m / force_n);
      // In the plane: u_x and u_z (u_y lies in another block of the band when the frame is
      // numbered for the linear couplings).
      const int carrier = model_.mesh().body_carrier[comb.body];
      constexpr std::array<int, 2> kInPlane = {0, 2};
      for (std::size_t i = 0; i < kInPlane.size(); ++i) {
        const int row = model_.CarrierDof(carrier, kInPlane[i]);
        if (row < 0) continue;
        force[row] -= pull[kInPlane[i]];
        for (std::size_t j = i; j < kInPlane.size(); ++j) {
          const int column = model_.CarrierDof(carrier, kInPlane[j]);
          if (column >= 0) tangent.band().Add(row, column, -hessian(kInPlane[i], kInPlane[j]));
        }
      }
    }
    return true;
  }

  /// The combs act on bodies, never on a member's element.
  FrameModel::ElementVector LocalForce(const Eigen::VectorXd& /*d*/, int /*e*/) const override {
    return FrameModel::ElementVector::Zero();
  }

 private:
  const FrameModel& model_;
  std::vector<CombDrive> combs_;
  double factor_ = 1.0;
};

}  // namespace cosmems
