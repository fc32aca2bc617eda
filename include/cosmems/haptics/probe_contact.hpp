#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <initializer_list>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/haptics/probe_faces.hpp"

namespace cosmems {

/// The probe pressing on the beam's faces (ProbeFaces pushes). The sphere's centre p is in the
/// beam's axes [m] (x along the axis from the first support, y away from the substrate, z across
/// the width); the beam is the box 0 <= x <= L, |z| <= b/2, |y - u_y(x)| <= t/2. Each face moves
/// along its axis by the beam's displacement at the face point under the sphere: Hermite cubics
/// for bending, the axial ends' u_x for the end faces. The upper and lower faces are the
/// rectangles 0 <= x <= L, |z| <= b/2 (their overlaps are both positive exactly when the sphere
/// meets the box); the sides and ends are taken unbounded in y (their overlaps only choose the
/// push).
///
/// In a 3-D model numbered node by node (DofNumbering::kByNode) the upper and lower faces also
/// turn with the twist r_x: their point at z_c across the width moves by u_y - r_x z_c, so a push
/// off the axis twists the beam. Numbered field by field, bending and torsion lie outside each
/// other's band and the twist is left out. The sides move with u_z (their small arm about the
/// axis, at most t/2, is left out); in a planar model they do not move: a rigid wall to the hand.
/// MoveTo() allocates nothing.
template <int Dim>
class ProbeContact final : public ProbeFaces {
 public:
  ProbeContact(const BeamModel<Dim>& model, const ProbeOptions& options)
      : ProbeFaces(model.units(), options) {
    const auto& elements = model.description().elements;
    const bool twisting = model.dofs().numbering() == DofNumbering::kByNode;
    for (int e = 0; e < model.ElementCount(); ++e) {
      Element element;
      element.x0 = model.NodeX()[e];
      element.h = model.elements()[e].properties().length;
      element.half_thickness = 0.5 * elements[e].section.thickness / units_.length;
      element.half_width = 0.5 * elements[e].section.width / units_.length;
      for (int node = 0; node < 2; ++node) {
        element.axial[node] = model.dofs().Reduced(e + node, NodalDof::kUx);
        element.bending_y[2 * node] = model.dofs().Reduced(e + node, NodalDof::kUy);
        element.bending_y[2 * node + 1] = model.dofs().Reduced(e + node, NodalDof::kRz);
        element.bending_z[2 * node] = model.dofs().Reduced(e + node, NodalDof::kUz);
        element.bending_z[2 * node + 1] = model.dofs().Reduced(e + node, NodalDof::kRy);
        element.twist[node] = twisting ? model.dofs().Reduced(e + node, NodalDof::kRx) : -1;
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
    const std::size_t index =
        static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - elements_.begin() - 1));
    const Element& e = elements_[index];
    const double xi = std::clamp((xc - e.x0) / e.h, 0.0, 1.0);
    const double dx = p.x() - xc;
    const double zc = std::clamp(p.z(), -e.half_width, e.half_width);
    const double dz = p.z() - zc;
    const double r2 = radius_ * radius_;
    // Beyond the strip by more than the radius (or NaN): nothing to touch.
    reach_ = dx * dx + dz * dz < r2;
    if (!reach_) return;
    const double over_face = std::sqrt(r2 - dx * dx - dz * dz);
    const double beside = std::sqrt(r2 - dx * dx);
    const double past_end = std::sqrt(r2 - dz * dz);

    const std::array<double, 4> hermite = HermiteShapes(xi);
    // u_y - r_x z_c at the face's point, r_x linear along the element.
    const Dofs across_y = {e.bending_y[0], e.bending_y[1], e.bending_y[2],
                           e.bending_y[3], e.twist[0],     e.twist[1]};
    const Weights along_y = PadWeights(
        {hermite[0], e.h * hermite[1], hermite[2], e.h * hermite[3], -zc * (1.0 - xi), -zc * xi});
    // x-z plane: the slope of u_z is -r_y.
    const Dofs across_z = {e.bending_z[0], e.bending_z[1], e.bending_z[2], e.bending_z[3], -1, -1};
    const Weights along_z =
        PadWeights({hermite[0], -e.h * hermite[1], hermite[2], -e.h * hermite[3]});
    const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(),
                          z = Eigen::Vector3d::UnitZ();
    Place(ProbeFace::kUpper, +1.0, e.half_thickness - p.y() + over_face, y, PadDofs(across_y),
          along_y);
    Place(ProbeFace::kLower, -1.0, e.half_thickness + p.y() + over_face, -y, PadDofs(across_y),
          along_y);
    Place(ProbeFace::kPositiveZ, +1.0, e.half_width - p.z() + beside, z, PadDofs(across_z),
          along_z);
    Place(ProbeFace::kNegativeZ, -1.0, e.half_width + p.z() + beside, -z, PadDofs(across_z),
          along_z);
    const Weights end = PadWeights({1.0});
    Place(ProbeFace::kFirstEnd, -1.0, p.x() + past_end, -x,
          PadDofs({elements_.front().axial[0], -1, -1, -1, -1, -1}), end);
    Place(ProbeFace::kLastEnd, +1.0, length_ - p.x() + past_end, x,
          PadDofs({elements_.back().axial[1], -1, -1, -1, -1, -1}), end);
  }

 private:
  // A face's point moves with at most six dofs: u_y, r_z of both nodes and their twists.
  using Dofs = std::array<int, 6>;  ///< reduced dofs (-1: supported or absent)
  using Weights = Eigen::Matrix<double, 12, 1>;

  struct Element {
    double x0 = 0.0, h = 0.0, half_thickness = 0.0, half_width = 0.0;
    std::array<int, 2> axial{};      ///< u_x of both nodes
    std::array<int, 4> bending_y{};  ///< u_y, r_z of both nodes
    std::array<int, 4> bending_z{};  ///< u_z, r_y of both nodes
    std::array<int, 2> twist{};      ///< r_x of both nodes (-1 when left out)
  };

  static std::array<int, 12> PadDofs(const Dofs& dofs) {
    std::array<int, 12> out;
    out.fill(-1);
    std::copy(dofs.begin(), dofs.end(), out.begin());
    return out;
  }
  static Weights PadWeights(std::initializer_list<double> weights) {
    Weights out = Weights::Zero();
    std::copy(weights.begin(), weights.end(), out.data());
    return out;
  }

  double length_ = 0.0;
  std::vector<Element> elements_;
};

}  // namespace cosmems
