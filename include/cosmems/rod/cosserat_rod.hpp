#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bitset>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cosmems/beam/beam_description.hpp"
#include "cosmems/beam/frame_layout.hpp"
#include "cosmems/beam/support.hpp"
#include "cosmems/core/units.hpp"
#include "cosmems/rod/block_tridiagonal_system.hpp"
#include "cosmems/rod/cosserat_element.hpp"
#include "cosmems/rod/cosserat_options.hpp"
#include "cosmems/rod/rod_loads.hpp"
#include "cosmems/rod/rod_state.hpp"
#include "cosmems/rod/so3.hpp"

namespace cosmems {

/// A geometrically exact Cosserat (Simo-Reissner) rod built from a BeamDescription: the same
/// elements (each with its material and section) and supports as the linear beam, in 3-D with
/// six degrees of freedom per node (u_x, u_y, u_z, then the spatial rotation increments
/// theta_x, theta_y, theta_z, in NodalDof order). This is the Model of the Model/Data split: built
/// once, then read by the static solver and the integrator, which hold the per-iteration
/// workspaces.
///
/// Internal units are the beam's (UnitSystem::ForBeam from the whole length and the first
/// element's E I_z and rho A), so the same rod at 100 nm and at 1 mm gives the same numbers.
/// Supports hold components of the spatial increments: a clamp fixes all six; a pinned node
/// fixes the translations and the twist increment about x (exact while the end's rotation stays
/// about one axis, as in plane bending).
///
/// Masses are lumped: each node carries half of its elements' rho A h and rho h (I_y + I_z, I_y,
/// I_z) about its own directors, which keeps the inertia block diagonal per node (a consistent
/// mass would couple nodes through the rotation-dependent frames at every step).
///
/// The description's axial_load N0 is a residual stress: the straight rod at its length carries
/// N0 (see CosseratElement::axial_prestress), so a bridge keeps it and stiffens by it in bending,
/// while a cantilever's free end lets it relax (shortening by N0 L / EA). series_order belongs to
/// the linear beam and is not used.
class CosseratRod {
 public:
  static constexpr int kNodeDofs = 6;

  explicit CosseratRod(const BeamDescription& description, CosseratOptions options = {})
      : description_((description.Validate(), description)),
        options_((options.Validate(), options)),
        units_(description.InternalUnits()) {
    double x = 0.0;
    node_x_.push_back(0.0);
    node_mass_.assign(description.NodeCount(), 0.0);
    node_inertia_.assign(description.NodeCount(), Eigen::Vector3d::Zero());
    for (std::size_t e = 0; e < description.elements.size(); ++e) {
      const ElementProperties p = ElementProperties::From(description.elements[e], units_);
      elements_.push_back(CosseratElement::From(p, options.shear_factor, options.ConstraintFactor(),
                                                description.axial_load / units_.force));
      x += p.length;
      node_x_.push_back(x);
      for (std::size_t node : {e, e + 1}) {
        node_mass_[node] += 0.5 * elements_.back().mass;
        node_inertia_[node] += 0.5 * elements_.back().rotary_inertia;
      }
    }
    for (const Support support : description.supports) {
      std::uint8_t mask = 0;
      for (int k = 0; k < kNodeDofs; ++k) {
        if (Fixes(support, static_cast<NodalDof>(k))) mask |= static_cast<std::uint8_t>(1u << k);
      }
      fixed_.push_back(mask);
      for (int k = 0; k < 3; ++k) {
        if (mask & (1u << k)) anchors_[k].push_back(static_cast<int>(fixed_.size()) - 1);
      }
    }
  }

  const BeamDescription& description() const { return description_; }
  const CosseratOptions& options() const { return options_; }
  const UnitSystem& units() const { return units_; }
  const std::vector<CosseratElement>& elements() const { return elements_; }

  int ElementCount() const { return static_cast<int>(elements_.size()); }
  int NodeCount() const { return ElementCount() + 1; }
  int DofCount() const { return kNodeDofs * NodeCount(); }
  /// Degrees of freedom no support holds.
  int FreeDofCount() const {
    int fixed = 0;
    for (const std::uint8_t mask : fixed_)
      fixed += static_cast<int>(std::bitset<kNodeDofs>(mask).count());
    return DofCount() - fixed;
  }
  /// Undeformed node positions along x (internal units: 0 ... 1 for the whole rod).
  const std::vector<double>& NodeX() const { return node_x_; }
  /// Lumped mass and rotary inertia about (d1, d2, d3) of a node (internal units).
  double NodeMass(int node) const { return node_mass_[node]; }
  const Eigen::Vector3d& NodeRotaryInertia(int node) const { return node_inertia_[node]; }
  /// Bit k set when the support of `node` holds its degree of freedom k (NodalDof order).
  std::uint8_t FixedMask(int node) const { return fixed_[node]; }

  /// A Newton matrix of this rod's pattern and supports.
  BlockTridiagonalSystem MakeSystem() const { return BlockTridiagonalSystem(fixed_); }
  RodState UndeformedState() const { return RodState::Undeformed(NodeCount()); }

  /// Converts SI loads into internal units in `out`; allocates nothing once `out` has the rod's
  /// shape. The dead forces must have one column per node.
  void ToInternal(const RodLoads& loads, RodLoads& out) const {
    out.dead_forces = loads.dead_forces / units_.force;
    out.follower_force = loads.follower_force / units_.force;
    out.end_moment = loads.end_moment / units_.Moment();
  }

  /// Per-element workspace of InternalForces() for InternalTangent().
  using ElementKinematics = std::vector<CosseratElement::Kinematics>;
  ElementKinematics MakeKinematics() const { return ElementKinematics(elements_.size()); }

  /// Sets `force` (DofCount() entries) to the internal forces dW/d(u, theta) and keeps in
  /// `kinematics` what InternalTangent() needs. Returns (sum over elements of |g_e|^2)^(1/2):
  /// the size of the forces the residual balances, for relative tests. Internal units;
  /// allocates nothing.
  double InternalForces(const RodState& state, Eigen::VectorXd& force,
                        ElementKinematics& kinematics) const {
    CosseratElement::Vector12 g;
    double size2 = 0.0;
    force.segment<6>(0).setZero();
    Eigen::Quaterniond qa = state.Rotation(0);
    for (int e = 0; e < ElementCount(); ++e) {
      const Eigen::Quaterniond qb = state.Rotation(e + 1);
      const Eigen::Vector3d du = state.displacement.col(e + 1) - state.displacement.col(e);
      elements_[e].Gradient(du, qa, qb, g, kinematics[e]);
      // Node e already holds element e-1's share; node e + 1 gets its first.
      force.segment<6>(kNodeDofs * e) += g.head<6>();
      force.segment<6>(kNodeDofs * (e + 1)) = g.tail<6>();
      size2 += g.squaredNorm();
      qa = qb;
    }
    return std::sqrt(size2);
  }

  /// Sets the diagonal and lower blocks of `tangent` to the elements' chart Hessians at the
  /// state InternalForces() saw (the unsymmetric block is SubtractLoads()'s). Allocates nothing.
  void InternalTangent(const ElementKinematics& kinematics, BlockTridiagonalSystem& tangent) const {
    CosseratElement::Tangent k;
    tangent.Diagonal(0).setZero();
    for (int e = 0; e < ElementCount(); ++e) {
      elements_[e].Hessian(kinematics[e], k);
      BlockTridiagonalSystem::Block& a = tangent.Diagonal(e);  // holds element e-1's share
      a.topLeftCorner<3, 3>() += k.force;
      a.bottomLeftCorner<3, 3>() += k.rotation_a_force;
      a.topRightCorner<3, 3>() += k.rotation_a_force.transpose();
      a.bottomRightCorner<3, 3>() += k.rotation_aa;
      BlockTridiagonalSystem::Block& b = tangent.Diagonal(e + 1);
      b.topLeftCorner<3, 3>() = k.force;
      b.bottomLeftCorner<3, 3>() = -k.rotation_b_force;
      b.topRightCorner<3, 3>() = -k.rotation_b_force.transpose();
      b.bottomRightCorner<3, 3>() = k.rotation_bb;
      BlockTridiagonalSystem::Block& ba = tangent.Lower(e);  // rows of b, columns of a
      ba.topLeftCorner<3, 3>() = -k.force;
      ba.topRightCorner<3, 3>() = -k.rotation_a_force.transpose();
      ba.bottomLeftCorner<3, 3>() = k.rotation_b_force;
      ba.bottomRightCorner<3, 3>() = k.rotation_ba;
    }
  }

  /// Subtracts the external loads (internal units, see ToInternal) from `residual` and, when
  /// `tangent` is given, sets its unsymmetric block to their load stiffness: [F]x in the (force,
  /// rotation) block of the last node for the follower force F = R_N F0, and -[M]x / 2 in its
  /// (rotation, rotation) block for the end moment (both are derivatives of the residual in the
  /// exponential chart). Returns the size of the applied load vector. Allocates nothing.
  double SubtractLoads(const RodState& state, const RodLoads& loads, Eigen::VectorXd& residual,
                       BlockTridiagonalSystem* tangent) const {
    const int last = NodeCount() - 1;
    for (int i = 0; i < NodeCount(); ++i) {
      residual.segment<3>(kNodeDofs * i) -= loads.dead_forces.col(i);
    }
    const Eigen::Vector3d follower = state.Rotation(last) * loads.follower_force;
    residual.segment<3>(kNodeDofs * last) -= follower;
    residual.segment<3>(kNodeDofs * last + 3) -= loads.end_moment;
    if (tangent != nullptr) {
      BlockTridiagonalSystem::Block& u = tangent->LastUnsymmetric();
      u.setZero();
      u.topRightCorner<3, 3>() = Skew(follower);
      u.bottomRightCorner<3, 3>() = -0.5 * Skew(loads.end_moment);
    }
    return std::sqrt(loads.dead_forces.squaredNorm() + follower.squaredNorm() +
                     loads.end_moment.squaredNorm());
  }

  /// The Newton update `out` = `state` (+) `step` x `increment`: rotations R_i <- exp(step
  /// theta_i^) R_i, and displacements u_i + step du_i plus a correction that turns each element's
  /// chord d with the element's rotation Q, the geodesic midpoint of exp(step theta_a^) and
  /// exp(step theta_b^) (the normalised sum of their quaternions; exp(step (theta_a + theta_b)^/2)
  /// to first order, and exactly when the two share an axis):
  ///   d' = Q (d + dd - omega x d)   (dd = step (du_b - du_a), omega = step (theta_a + theta_b)/2),
  /// which is d + dd to first order (Newton's step is unchanged there) but does not stretch the
  /// chord by |omega|^2 / 2 as the plain update d + dd does. For a slender rod that stretch is an
  /// axial force EA |omega|^2 / 2 (EA L^2 / EI = 1.2e5 for the reference cantilever) which swamps
  /// the loads and makes Newton crawl; and where the linear step already has the right rotations
  /// (a pure end moment: theta linear in s, up to 2 pi) this update puts the nodes on the circle.
  /// The chord corrections are summed along the rod; at supports that hold a translation the sum
  /// is brought back to zero by subtracting its linear interpolant between such nodes.
  /// `correction` is a workspace of 3 x NodeCount(). Allocates nothing.
  void Retract(const RodState& state, const Eigen::VectorXd& increment, double step, RodState& out,
               Eigen::Matrix3Xd& correction) const {
    // The nodes' rotation increments, kept in `out` until the chords have used them.
    for (int i = 0; i < NodeCount(); ++i) {
      out.rotation.col(i) = QuaternionExp(step * increment.segment<3>(kNodeDofs * i + 3)).coeffs();
    }
    correction.col(0).setZero();
    for (int e = 0; e < ElementCount(); ++e) {
      // The sum of the pair's quaternions in one hemisphere: the midpoint of the rotations.
      const double sign = out.rotation.col(e).dot(out.rotation.col(e + 1)) < 0.0 ? -1.0 : 1.0;
      Eigen::Quaterniond q;
      q.coeffs() = out.rotation.col(e) + sign * out.rotation.col(e + 1);
      q.normalize();
      const Eigen::Vector3d omega =
          (0.5 * step) * (increment.segment<3>(6 * e + 3) + increment.segment<3>(6 * e + 9));
      const Eigen::Vector3d dd =
          step * (increment.segment<3>(6 * e + 6) - increment.segment<3>(6 * e));
      const Eigen::Vector3d d = elements_[e].length * Eigen::Vector3d::UnitX() +
                                state.displacement.col(e + 1) - state.displacement.col(e);
      const Eigen::Vector3d moved = d + dd;
      correction.col(e + 1) = correction.col(e) + q * (moved - omega.cross(d)) - moved;
    }
    for (int k = 0; k < 3; ++k) {
      const std::vector<int>& anchors = anchors_[k];
      if (anchors.empty()) continue;
      for (int i = 0; i < NodeCount(); ++i) {  // the interpolant through the anchors' values
        const auto next = std::lower_bound(anchors.begin(), anchors.end(), i);
        double value = 0.0;
        if (next == anchors.begin()) {
          value = correction(k, anchors.front());
        } else if (next == anchors.end()) {
          value = correction(k, anchors.back());
        } else {
          const int a = *(next - 1);
          const int b = *next;
          const double s = (node_x_[i] - node_x_[a]) / (node_x_[b] - node_x_[a]);
          value = (1.0 - s) * correction(k, a) + s * correction(k, b);
        }
        correction(k, i) -= value;
      }
    }
    for (int i = 0; i < NodeCount(); ++i) {
      out.displacement.col(i) = state.displacement.col(i) +
                                step * increment.segment<3>(kNodeDofs * i) + correction.col(i);
      Eigen::Quaterniond q = out.Rotation(i) * state.Rotation(i);
      q.normalize();
      out.rotation.col(i) = q.coeffs();
    }
  }

  /// Zeroes the entries of supported degrees of freedom (their residuals are reactions).
  void ClearSupported(Eigen::Ref<Eigen::VectorXd> vector) const {
    for (int i = 0; i < NodeCount(); ++i) {
      if (fixed_[i] == 0) continue;
      for (int k = 0; k < kNodeDofs; ++k) {
        if (fixed_[i] & (1u << k)) vector[kNodeDofs * i + k] = 0.0;
      }
    }
  }

  /// Strain energy (internal units).
  double StrainEnergy(const RodState& state) const {
    double w = 0.0;
    for (int e = 0; e < ElementCount(); ++e) {
      w += elements_[e].Energy(state.displacement.col(e + 1) - state.displacement.col(e),
                               state.Rotation(e), state.Rotation(e + 1));
    }
    return w;
  }

  /// Deformed node positions [m], one column per node.
  Eigen::Matrix3Xd NodePositions(const RodState& state) const {
    Eigen::Matrix3Xd x = state.displacement;
    for (int i = 0; i < NodeCount(); ++i) x(0, i) += node_x_[i];
    return units_.length * x;
  }

  /// Displacement [m] at `x` [m] along the undeformed axis, interpolated linearly between nodes
  /// as the elements do (a node's own when x falls on it; e.g. the midspan of a bridge).
  Eigen::Vector3d DisplacementAt(const RodState& state, double x) const {
    const double xi = x / units_.length;
    const auto it = std::upper_bound(node_x_.begin(), node_x_.end(), xi);
    const int e = std::clamp(static_cast<int>(it - node_x_.begin()) - 1, 0, ElementCount() - 1);
    const double s = std::clamp((xi - node_x_[e]) / elements_[e].length, 0.0, 1.0);
    return units_.length *
           ((1.0 - s) * state.displacement.col(e) + s * state.displacement.col(e + 1));
  }

  /// Displacement of the last node [m].
  Eigen::Vector3d TipDisplacement(const RodState& state) const {
    return units_.length * state.displacement.col(NodeCount() - 1);
  }

  /// Rotation vector of the last node [rad] (rx, ry, rz), lifted continuously node by node from
  /// the first: it passes pi instead of wrapping, and a rod rolled into a full circle about z
  /// reports (0, 0, 2 pi). (No rotation vector follows every path continuously: near a multiple
  /// of 2 pi a small out-of-plane part can tip the axis, and the lift then falls back to the
  /// principal vector. Plane deformations, the MEMS case, and 3-D ones that stay away from
  /// 2 pi k are exact.)
  Eigen::Vector3d TipRotation(const RodState& state) const {
    Eigen::Vector3d theta = QuaternionLog(state.Rotation(0));
    for (int i = 1; i < NodeCount(); ++i) theta = RotationVectorNear(state.Rotation(i), theta);
    return theta;
  }

  /// Stress resultants of element e at its midpoint, on its directors: force [N] (axial,
  /// shear along d2, shear along d3; tension > 0) and moment [N m] (twist, bending about d2,
  /// bending about d3).
  void ElementResultants(const RodState& state, int e, Eigen::Vector3d& force,
                         Eigen::Vector3d& moment) const {
    elements_[e].Resultants(state.displacement.col(e + 1) - state.displacement.col(e),
                            state.Rotation(e), state.Rotation(e + 1), force, moment);
    force *= units_.force;
    moment *= units_.Moment();
  }

  /// The axial force [N] averaged over the length (tension > 0): for a bridge the N of the
  /// stretching theory, for a cantilever under a transverse tip force close to zero.
  double AxialForce(const RodState& state) const {
    double sum = 0.0;
    Eigen::Vector3d force, moment;
    for (int e = 0; e < ElementCount(); ++e) {
      ElementResultants(state, e, force, moment);
      sum += elements_[e].length * force.x();
    }
    return sum / node_x_.back();
  }

 private:
  BeamDescription description_;
  CosseratOptions options_;
  UnitSystem units_;
  std::vector<CosseratElement> elements_;
  std::vector<double> node_x_;
  std::vector<double> node_mass_;
  std::vector<Eigen::Vector3d> node_inertia_;
  std::vector<std::uint8_t> fixed_;
  std::array<std::vector<int>, 3> anchors_;  // nodes whose translation k is held
};

}  // namespace cosmems
