#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
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

/// The faces of the beam's box, each pushed along one axis: the upper face (away from the
/// substrate), the lower face, the sides at +z and -z, and the end faces at x = 0 and x = L.
enum class ProbeFace { kUpper = 0, kLower, kPositiveZ, kNegativeZ, kFirstEnd, kLastEnd };
inline constexpr int kProbeFaceCount = 6;

/// Where the probe meets the beam at a state: the face it presses on (or is nearest to), its
/// outward normal, the depth along it [m] (negative: the clearance; -inf: out of reach) and the
/// force the beam pushes the probe with along the normal [N] (>= 0).
struct ProbeTouch {
  ProbeFace face = ProbeFace::kUpper;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double depth_m = -std::numeric_limits<double>::infinity();
  double force_n = 0.0;
};

/// The probe pressing on the beam's faces, as a NonlinearForce. The sphere's centre p is in the
/// beam's axes [m] (x along the axis from the first support, y away from the substrate, z across
/// the width); the beam is the box 0 <= x <= L, |z| <= b/2, |y - u_y(x)| <= t/2.
///
/// Each face f, moved along its axis a by the beam's displacement u_a at the face point under
/// the sphere, overlaps the sphere by
///   delta_f(d) = s_f (c_f + u_a(x_f) - p_a) + sqrt(r^2 - h_f^2),
/// s_f = +-1 the side of the face, c_f its undeformed place, h_f the distance from p to the face
/// across the face's plane. The upper and lower faces are the rectangles 0 <= x <= L, |z| <= b/2
/// (their overlaps are both positive exactly when the sphere meets the box); the sides and ends
/// are taken unbounded in y (their overlaps only choose the push). A sphere that meets the box
/// is pushed out through the face it came in by: the face of least overlap when contact begins
/// (the separating-axis push), held from one accepted step to the next until its overlap ends,
/// so a hand pressing deeper than the beam's half thickness never pops through to the other face
/// (Zilles & Salisbury's god object keeps its face the same way). With delta the held face's
/// overlap, the coupling's energy (k/2) delta^2 gives r(d) = k delta s_f N_f and
/// dr/dd = k N_f N_f^T, N_f the interpolation of u_a (Hermite cubics for bending, linear for the
/// axial ends), each delta_f being affine in d.
///
/// In a 3-D model numbered node by node (DofNumbering::kByNode) the upper and lower faces also
/// turn with the twist r_x: their point at z_c across the width moves by u_y - r_x z_c, so a push
/// off the axis twists the beam. Numbered field by field, bending and torsion lie outside each
/// other's band and the twist is left out. The sides move with u_z (their small arm about the
/// axis, at most t/2, is left out); in a planar model they do not move: a rigid wall to the hand.
/// MoveTo() and Evaluate() allocate nothing.
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
    const Shapes along_y = {hermite[0],       e.h * hermite[1], hermite[2],
                            e.h * hermite[3], -zc * (1.0 - xi), -zc * xi};
    // x-z plane: the slope of u_z is -r_y.
    const Dofs across_z = {e.bending_z[0], e.bending_z[1], e.bending_z[2], e.bending_z[3], -1, -1};
    const Shapes along_z = {hermite[0], -e.h * hermite[1], hermite[2], -e.h * hermite[3], 0.0, 0.0};
    Place(ProbeFace::kUpper, +1.0, e.half_thickness - p.y() + over_face, across_y, along_y);
    Place(ProbeFace::kLower, -1.0, e.half_thickness + p.y() + over_face, across_y, along_y);
    Place(ProbeFace::kPositiveZ, +1.0, e.half_width - p.z() + beside, across_z, along_z);
    Place(ProbeFace::kNegativeZ, -1.0, e.half_width + p.z() + beside, across_z, along_z);
    const Shapes end_shape = {1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    Place(ProbeFace::kFirstEnd, -1.0, p.x() + past_end,
          {elements_.front().axial[0], -1, -1, -1, -1, -1}, end_shape);
    Place(ProbeFace::kLastEnd, +1.0, length_ - p.x() + past_end,
          {elements_.back().axial[1], -1, -1, -1, -1, -1}, end_shape);
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    if (!reach_) return true;
    const auto [face, delta] = Pushing(d);
    if (!std::isfinite(delta)) return false;
    if (delta <= 0.0) return true;
    const Face& f = faces_[static_cast<std::size_t>(face)];
    for (int i = 0; i < kFaceDofs; ++i) {
      if (f.dof[i] < 0) continue;
      force[f.dof[i]] += stiffness_ * delta * f.sign * f.shape[i];
      for (int j = i; j < kFaceDofs; ++j) {
        if (f.dof[j] >= 0)
          tangent.band().Add(f.dof[i], f.dof[j], stiffness_ * f.shape[i] * f.shape[j]);
      }
    }
    return true;
  }

  /// Idle: out of reach, or clear of every face (the spring, zero at contact, then stays zero
  /// around d).
  bool Idle(const Eigen::VectorXd& d) const override { return !reach_ || Pushing(d).second < 0.0; }

  /// The step ending at d is accepted: the face pushing there is held while contact lasts.
  void Commit(const Eigen::VectorXd& d) override {
    if (!reach_) {
      held_ = kNoFace;
      return;
    }
    const auto [face, delta] = Pushing(d);
    held_ = delta > 0.0 ? static_cast<int>(face) : kNoFace;
  }

  /// The face the probe presses on (or is nearest to) at d, and how deep.
  ProbeTouch Touch(const Eigen::VectorXd& d) const {
    ProbeTouch touch;
    if (!reach_) return touch;
    const auto [face, delta] = Pushing(d);
    touch.face = face;
    touch.normal = Normal(face);
    touch.depth_m = delta * units_.length;
    touch.force_n = delta > 0.0 ? stiffness_ * delta * units_.force : 0.0;
    return touch;
  }
  /// The shape vector N_f of the face's point under the probe (reduced dofs, internal units), for
  /// the beam's compliance there; zero for a face that does not move.
  void ShapeVector(ProbeFace face, Eigen::VectorXd& n) const {
    n.setZero();
    const Face& f = faces_[static_cast<std::size_t>(face)];
    for (int i = 0; i < kFaceDofs; ++i) {
      if (f.dof[i] >= 0) n[f.dof[i]] = f.shape[i];
    }
  }
  double stiffness_n_per_m() const { return stiffness_ * units_.force / units_.length; }

  /// The outward normal of a face in the beam's axes.
  static Eigen::Vector3d Normal(ProbeFace face) {
    switch (face) {
      case ProbeFace::kUpper:
        return Eigen::Vector3d::UnitY();
      case ProbeFace::kLower:
        return -Eigen::Vector3d::UnitY();
      case ProbeFace::kPositiveZ:
        return Eigen::Vector3d::UnitZ();
      case ProbeFace::kNegativeZ:
        return -Eigen::Vector3d::UnitZ();
      case ProbeFace::kFirstEnd:
        return -Eigen::Vector3d::UnitX();
      case ProbeFace::kLastEnd:
        break;
    }
    return Eigen::Vector3d::UnitX();
  }

 private:
  // A face's point moves with at most six dofs: u_y, r_z of both nodes and their twists.
  static constexpr int kFaceDofs = 6;
  using Dofs = std::array<int, kFaceDofs>;  ///< reduced dofs (-1: supported or absent)
  using Shapes = std::array<double, kFaceDofs>;

  struct Element {
    double x0 = 0.0, h = 0.0, half_thickness = 0.0, half_width = 0.0;
    std::array<int, 2> axial{};      ///< u_x of both nodes
    std::array<int, 4> bending_y{};  ///< u_y, r_z of both nodes
    std::array<int, 4> bending_z{};  ///< u_z, r_y of both nodes
    std::array<int, 2> twist{};      ///< r_x of both nodes (-1 when left out)
  };

  // One face at the probe's place: delta = sign * (shape . d[dof]) + constant.
  struct Face {
    Dofs dof{-1, -1, -1, -1, -1, -1};
    Shapes shape{};
    double sign = 1.0, constant = 0.0;
  };

  void Place(ProbeFace face, double sign, double constant, const Dofs& dof, const Shapes& shape) {
    faces_[static_cast<std::size_t>(face)] = Face{dof, shape, sign, constant};
  }

  static double Overlap(const Face& f, const Eigen::VectorXd& d) {
    double u = 0.0;
    for (int i = 0; i < kFaceDofs; ++i) {
      if (f.dof[i] >= 0) u += f.shape[i] * d[f.dof[i]];
    }
    return f.sign * u + f.constant;
  }

  // The face pushing the sphere and its overlap (internal units; the sphere is in reach): the
  // held face while contact lasts, else the face of least overlap.
  std::pair<ProbeFace, double> Pushing(const Eigen::VectorXd& d) const {
    if (held_ == kNoFace) return Deepest(d);
    return {static_cast<ProbeFace>(held_), Overlap(faces_[static_cast<std::size_t>(held_)], d)};
  }

  // The face of least overlap and that overlap.
  std::pair<ProbeFace, double> Deepest(const Eigen::VectorXd& d) const {
    ProbeFace face = ProbeFace::kUpper;
    double least = std::numeric_limits<double>::infinity();
    for (int f = 0; f < kProbeFaceCount; ++f) {
      const double overlap = Overlap(faces_[static_cast<std::size_t>(f)], d);
      if (std::isnan(overlap)) return {static_cast<ProbeFace>(f), overlap};  // reported
      if (overlap < least) {
        least = overlap;
        face = static_cast<ProbeFace>(f);
      }
    }
    return {face, least};
  }

  UnitSystem units_;
  double radius_, stiffness_;
  double length_ = 0.0;
  std::vector<Element> elements_;
  bool reach_ = false;
  std::array<Face, kProbeFaceCount> faces_{};
  static constexpr int kNoFace = -1;
  int held_ = kNoFace;  ///< the face pushing at the last accepted step
};

}  // namespace cosmems
