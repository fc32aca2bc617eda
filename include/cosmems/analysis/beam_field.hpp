#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/element_interpolation.hpp"

namespace cosmems {

/// Displacements, rotations, curvatures and stresses along a beam, recovered from a reduced
/// nodal solution with the static shape functions. Inputs and outputs in SI.
template <int Dim>
class BeamField {
 public:
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  using Local = Eigen::Matrix<double, FrameElement<Dim>::kDofs, 1>;

  /// `reduced` in the model's internal units (as the solvers return it).
  BeamField(const BeamModel<Dim>& model, const Eigen::VectorXd& reduced)
      : model_(model), reduced_(reduced) {}

  /// [ux, uy, uz, rx, ry, rz] at x [m]: metres and radians.
  Vector6 At(double x) const {
    const auto [e, xi] = model_.Locate(x / model_.units().length);
    return AtElement(e, xi);
  }

  /// The same at every node, one row per node.
  Eigen::MatrixXd AtNodes() const {
    Eigen::MatrixXd out(model_.NodeCount(), 6);
    for (int n = 0; n < model_.NodeCount(); ++n) {
      out.row(n) = n < model_.ElementCount() ? AtElement(n, 0.0) : AtElement(n - 1, 1.0);
    }
    return out;
  }

  /// Largest deflection toward the substrate (-uy) [m], over nodes and element midpoints;
  /// zero when the beam moves only away from it.
  double MaxDeflectionTowardSubstrate() const {
    double most = 0.0;
    for (int e = 0; e < model_.ElementCount(); ++e) {
      for (double xi : {0.0, 0.5, 1.0}) most = std::max(most, -AtElement(e, xi)[1]);
    }
    return most;
  }

  /// Axial force N = N0 + EA du/dx in element e [N], tension positive, the residual N0 included.
  double AxialForce(int e) const {
    const Local q = LocalValues(e);
    const ElementProperties& p = model_.elements()[e].properties();
    const double strain = (q[kUx1] - q[kUx0]) / p.length;
    return (model_.AxialLoad() + p.young_modulus * p.area * strain) * model_.units().force;
  }

  /// The largest normal stress [Pa] at the outer fibres: |N + added_axial_force| / A +
  /// E |k_y| t/2 + E |k_z| b/2 with N = AxialForce(e), over both ends of every element (the
  /// static curvature is linear along an element, so its extremes sit at the ends).
  /// `added_axial_force` [N] is an axial force the displacements do not carry: a stretching
  /// beam's tension from its deflection.
  double MaxStress(double added_axial_force = 0.0) const {
    double most = 0.0;
    for (int e = 0; e < model_.ElementCount(); ++e) {
      const ElementProperties& p = model_.elements()[e].properties();
      const Local q = LocalValues(e);
      const double axial =
          std::abs(AxialForce(e) + added_axial_force) / model_.units().force / p.area;
      for (double xi : {0.0, 1.0}) {
        const ShapeValues s = ShapeValues::At(model_.bases(), xi);
        const double ky =
            Bending(q, s.bending_curvature, kUy0, kRz0, 1.0, p.length) / (p.length * p.length);
        double stress = axial + p.young_modulus * std::abs(ky) * p.half_thickness;
        if constexpr (Dim == 3) {
          const double kz =
              Bending(q, s.bending_curvature, kUz0, kRy0, -1.0, p.length) / (p.length * p.length);
          stress += p.young_modulus * std::abs(kz) * p.half_width;
        }
        most = std::max(most, stress);
      }
    }
    return most * model_.units().Stress();
  }

 private:
  static constexpr int kN = FrameLayout<Dim>::kNodeDofs;
  static constexpr int Idx(NodalDof d) { return FrameLayout<Dim>::kIndex[static_cast<int>(d)]; }
  static constexpr int kUx0 = Idx(NodalDof::kUx), kUx1 = kN + Idx(NodalDof::kUx);
  static constexpr int kUy0 = Idx(NodalDof::kUy), kRz0 = Idx(NodalDof::kRz);
  static constexpr int kUz0 = Idx(NodalDof::kUz), kRy0 = Idx(NodalDof::kRy);
  static constexpr int kRx0 = Idx(NodalDof::kRx);

  Local LocalValues(int e) const {
    Local q = Local::Zero();
    for (int a = 0; a < FrameElement<Dim>::kDofs; ++a) {
      const int r = model_.ElementDof(e, a);
      if (r >= 0) q[a] = reduced_[r];
    }
    return q;
  }

  // A bending field from Hermite weights h: nodal values (u, sign * l * r) at both nodes.
  static double Bending(const Local& q, const std::array<double, 4>& h, int u, int r, double sign,
                        double l) {
    return h[0] * q[u] + h[1] * sign * l * q[r] + h[2] * q[kN + u] + h[3] * sign * l * q[kN + r];
  }

  Vector6 AtElement(int e, double xi) const {
    const Local q = LocalValues(e);
    const double l = model_.elements()[e].properties().length;
    const ShapeValues s = ShapeValues::At(model_.bases(), xi);
    const double length_unit = model_.units().length;
    Vector6 out = Vector6::Zero();
    out[0] = (s.bar[0] * q[kUx0] + s.bar[1] * q[kUx1]) * length_unit;
    out[1] = Bending(q, s.bending, kUy0, kRz0, 1.0, l) * length_unit;
    out[5] = Bending(q, s.bending_slope, kUy0, kRz0, 1.0, l) / l;
    if constexpr (Dim == 3) {
      out[2] = Bending(q, s.bending, kUz0, kRy0, -1.0, l) * length_unit;
      out[3] = s.bar[0] * q[kRx0] + s.bar[1] * q[kN + kRx0];
      out[4] = -Bending(q, s.bending_slope, kUz0, kRy0, -1.0, l) / l;
    }
    return out;
  }

  const BeamModel<Dim>& model_;
  Eigen::VectorXd reduced_;
};

}  // namespace cosmems
