#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// The stylus tip in the micro world: a sphere of `radius` [m] tied to the hand by the virtual
/// coupling, a spring of `stiffness` [N/m] (Colgate, Stanley & Brown; Adams & Hannaford): the
/// hand feels at most this stiffness, whatever the beam does, so choosing it within the device's
/// renderable stiffness keeps the loop stable.
struct ProbeOptions {
  double radius = 2e-6;    ///< m
  double stiffness = 0.0;  ///< N/m, the coupling spring (required, > 0)
};

/// The probe pressing on the beam's upper face, as a NonlinearForce. The sphere's centre p is in
/// the beam's axes [m] (x along the axis from the first support, y away from the substrate, z
/// across the width). The face point under it is the closest point of the strip 0 <= x <= L,
/// |z| <= b/2; with h the horizontal distance to it (0 above the strip), the sphere's lowest
/// point over it is p_y - sqrt(r^2 - h^2) and the penetration is
///   delta(d) = w(x_c) + t/2 - (p_y - sqrt(r^2 - h^2)),
/// w(x_c) = N(x_c) . d the Hermite interpolation of u_y. The coupling's energy (k/2) max(delta,0)^2
/// gives r(d) = k delta N and dr/dd = k N N^T; the beam pushes the probe up with k delta.
/// The force acts on the axis: an offset across the width would also twist a 3-D beam, which
/// this neglects. MoveTo() and Evaluate() allocate nothing.
template <int Dim>
class ProbeContact final : public NonlinearForce {
 public:
  ProbeContact(const BeamModel<Dim>& model, const ProbeOptions& options)
      : units_(model.units()),
        radius_(options.radius / model.units().length),
        stiffness_(options.stiffness / (model.units().force / model.units().length)) {
    RequirePositive("probe.radius", options.radius);
    RequirePositive("probe.stiffness", options.stiffness);
    const auto& elements = model.description().elements;
    for (int e = 0; e < model.ElementCount(); ++e) {
      Element element;
      element.x0 = model.NodeX()[e];
      element.h = model.elements()[e].properties().length;
      element.half_thickness = 0.5 * elements[e].section.thickness / units_.length;
      element.half_width = 0.5 * elements[e].section.width / units_.length;
      for (int node = 0; node < 2; ++node) {
        element.dof[2 * node] = model.ElementDof(e, Index(node, NodalDof::kUy));
        element.dof[2 * node + 1] = model.ElementDof(e, Index(node, NodalDof::kRz));
      }
      elements_.push_back(element);
    }
    length_ = model.NodeX().back();
  }

  /// Places the sphere's centre at `centre_m` [m, beam axes].
  void MoveTo(const Eigen::Vector3d& centre_m) {
    const Eigen::Vector3d p = centre_m / units_.length;
    const double xc = std::clamp(p.x(), 0.0, length_);
    const auto it = std::upper_bound(elements_.begin(), elements_.end(), xc,
                                     [](double x, const Element& e) { return x < e.x0; });
    element_ = static_cast<int>(std::max<std::ptrdiff_t>(0, it - elements_.begin() - 1));
    const Element& e = elements_[static_cast<std::size_t>(element_)];
    xi_ = std::clamp((xc - e.x0) / e.h, 0.0, 1.0);
    const double zc = std::clamp(p.z(), -e.half_width, e.half_width);
    const double h2 = (p.x() - xc) * (p.x() - xc) + (p.z() - zc) * (p.z() - zc);
    // Beyond the strip's edge by more than the radius (or NaN): nothing to touch.
    reach_ = h2 < radius_ * radius_;
    const double lowest = p.y() - (reach_ ? std::sqrt(radius_ * radius_ - h2) : 0.0);
    offset_ = e.half_thickness - lowest;
    shapes_ = HermiteShapes(xi_);
    shapes_[1] *= e.h;
    shapes_[3] *= e.h;
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    if (!reach_) return true;
    const double delta = PenetrationInternal(d);
    if (!std::isfinite(delta)) return false;
    if (delta <= 0.0) return true;
    const std::array<int, 4>& dof = elements_[static_cast<std::size_t>(element_)].dof;
    for (int i = 0; i < 4; ++i) {
      if (dof[i] < 0) continue;
      force[dof[i]] += stiffness_ * delta * shapes_[i];
      for (int j = i; j < 4; ++j) {
        if (dof[j] >= 0) tangent.band().Add(dof[i], dof[j], stiffness_ * shapes_[i] * shapes_[j]);
      }
    }
    return true;
  }

  /// How deep the sphere sits in the beam at d [m]; negative: the clearance above it (-inf when
  /// it is beside the beam).
  double Penetration(const Eigen::VectorXd& d) const {
    return PenetrationInternal(d) * units_.length;
  }
  /// The force the beam pushes the probe up with at d [N] (>= 0).
  double Reaction(const Eigen::VectorXd& d) const {
    return stiffness_ * std::max(0.0, PenetrationInternal(d)) * units_.force;
  }
  /// The beam's deflection u_y under the probe at d [m].
  double Deflection(const Eigen::VectorXd& d) const { return Interpolate(d) * units_.length; }
  /// The shape vector N of the point under the probe (reduced dofs, internal units), for the
  /// beam's compliance there.
  void ShapeVector(Eigen::VectorXd& n) const {
    n.setZero();
    const std::array<int, 4>& dof = elements_[static_cast<std::size_t>(element_)].dof;
    for (int i = 0; i < 4; ++i) {
      if (dof[i] >= 0) n[dof[i]] = shapes_[i];
    }
  }
  double stiffness_n_per_m() const { return stiffness_ * units_.force / units_.length; }

 private:
  struct Element {
    double x0 = 0.0, h = 0.0, half_thickness = 0.0, half_width = 0.0;
    std::array<int, 4> dof{};  ///< reduced u_y, theta_z of both nodes (-1: supported)
  };

  static int Index(int node, NodalDof dof) {
    return node * FrameLayout<Dim>::kNodeDofs + FrameLayout<Dim>::kIndex[static_cast<int>(dof)];
  }

  double Interpolate(const Eigen::VectorXd& d) const {
    const std::array<int, 4>& dof = elements_[static_cast<std::size_t>(element_)].dof;
    double w = 0.0;
    for (int i = 0; i < 4; ++i) {
      if (dof[i] >= 0) w += shapes_[i] * d[dof[i]];
    }
    return w;
  }

  double PenetrationInternal(const Eigen::VectorXd& d) const {
    if (!reach_) return -std::numeric_limits<double>::infinity();
    return Interpolate(d) + offset_;
  }

  UnitSystem units_;
  double radius_, stiffness_;
  double length_ = 0.0;
  std::vector<Element> elements_;
  int element_ = 0;
  double xi_ = 0.0;
  bool reach_ = false;
  double offset_ = 0.0;
  std::array<double, 4> shapes_{};
};

}  // namespace cosmems
