#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/core/gauss_legendre.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/dof_weights.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/electrode.hpp"

namespace cosmems {

/// Which points of the faces over the substrate a FrameGapPoints holds.
enum class FrameGapLayout {
  kQuadrature,  ///< Gauss-Legendre points over the electrodes, with their areas: for pressures
  /// Where a face can touch the substrate first, with no area: each member element's nodes and
  /// quarter points on its lower face's centre line (the element's end only at its member's last
  /// element, so a node is held once), each body's four lower corners (a rigid plate's lowest
  /// points, however it tilts). For the substrate contact (FrameSubstrateContact).
  kContact,
};

/// Where a force across the gap acts on a frame: the substrate plane `gap` below the structure's
/// lowest face at rest, and the electrodes on it (by default one under all of the structure).
struct FrameGapOptions {
  double gap = 0.0;  ///< m
  std::vector<Electrode> electrodes = {Electrode{}};
  /// Gauss-Legendre points along each element's part over an electrode, and along each side of
  /// a body's rectangle over one.
  int points = 4;
  FrameGapLayout layout = FrameGapLayout::kQuadrature;
  /// m: the contact plane's height above the substrate when the scene has contact, which holds
  /// the gap from below (Gap()), as on the beam (GapSpan::separation); 0: no contact.
  double separation = 0.0;
};

/// The quadrature points of a frame's faces over the electrodes of the substrate, each with its
/// gap at rest, its area and how far it moves toward +y per unit of each degree of freedom it
/// depends on: the shared geometry of the forces across the gap (FrameGapForce, FrameSqueezeFilm).
///
/// A member parallel to the substrate is a strip as wide as its section seen from below; its
/// deflection toward the substrate is the Hermite cubic of its element (the static shape, as on
/// the beam), its part over an electrode clipped where its axis crosses the electrode's edges.
/// A member that is not parallel to the substrate shows it only an end, and has no points. A
/// body is a plate, its lower face at g_0 + u_y + theta_z (x - x_c) - theta_x (z - z_c), its
/// rectangle clipped by each electrode and integrated by a tensor Gauss rule. The members'
/// points come first, element by element, then the bodies'.
class FrameGapPoints {
 public:
  /// Its weights are its motion toward +y.
  struct Point : DofWeights {
    double gap_m = 0.0;    ///< at rest
    double area_m2 = 0.0;  ///< its share of the face
    double width_m = 0.0;  ///< the strip's width, or a plate's narrower side
    /// on a member, the local u_y weights of its element (for the element's share)
    FrameModel::ElementVector local = FrameModel::ElementVector::Zero();
  };

  /// Throws std::invalid_argument for a gap that is not positive, an electrode that is empty or
  /// two electrodes that overlap (a force would count twice where they do).
  FrameGapPoints(const FrameModel& model, const FrameGapOptions& options)
      : model_(model), length_m_(model.units().length) {
    RequirePositive("gap", options.gap);
    RequireWithin("separation", options.separation, 0.0, 0.5 * options.gap);
    separation_m_ = options.separation;
    RequireWithin("quadrature points", options.points, 1, 64);
    const std::vector<Electrode>& electrodes = options.electrodes;
    for (std::size_t i = 0; i < electrodes.size(); ++i) {
      const Electrode& a = electrodes[i];
      if (!(a.x[0] < a.x[1] && a.z[0] < a.z[1])) {
        throw std::invalid_argument("electrodes[" + std::to_string(i) + "]: empty rectangle");
      }
      for (std::size_t j = 0; j < i; ++j) {
        const auto overlap = electrodes[j].Clip(a.x, a.z);
        if (overlap[0][0] < overlap[0][1] && overlap[1][0] < overlap[1][1]) {
          throw std::invalid_argument("electrodes[" + std::to_string(i) + "] overlaps electrodes[" +
                                      std::to_string(j) + "]");
        }
      }
    }
    substrate_m_ = LowestFace() - options.gap;
    const bool contact = options.layout == FrameGapLayout::kContact;
    // The contact's points carry no weight (no area): they are held, not integrated.
    const GaussLegendre rule = contact ? GaussLegendre{{0.0, 0.25, 0.5, 0.75}, {0.0, 0.0, 0.0, 0.0}}
                                       : GaussLegendre::Of(options.points);
    GaussLegendre last = rule;  // a member's last element: its far end too
    if (contact) {
      last.points.push_back(1.0);
      last.weights.push_back(0.0);
    }
    const GaussLegendre corners{{0.0, 1.0}, {0.0, 0.0}};
    const std::vector<FrameMesh::Element>& elements = model.mesh().elements;
    first_point_.push_back(0);
    for (int e = 0; e < model.ElementCount(); ++e) {
      const bool member_ends =
          e + 1 == model.ElementCount() || elements[e + 1].member != elements[e].member;
      for (const Electrode& electrode : electrodes) {
        PlaceOnElement(e, electrode, contact && member_ends ? last : rule);
      }
      first_point_.push_back(static_cast<int>(points_.size()));
    }
    for (std::size_t b = 0; b < model.description().bodies.size(); ++b) {
      for (const Electrode& electrode : electrodes) {
        PlaceOnBody(static_cast<int>(b), electrode, contact ? corners : rule);
      }
    }
  }

  const std::vector<Point>& points() const { return points_; }
  /// Element e's points: [first(e), first(e + 1)); first(ElementCount()) ends the members'.
  int first(int e) const { return first_point_[e]; }
  /// The substrate plane's y [m].
  double substrate_m() const { return substrate_m_; }
  /// metres per internal length unit
  double length_m() const { return length_m_; }

  /// The point's gap [m] at the displacement d (internal units), at least the separation when
  /// there is one (NaN stays NaN): an iterate the contact's penalty lets through the contact
  /// plane meets the pressure there, not one growing like 1/g^n, which would outgrow the
  /// penalty and lift every touching iterate off again (as on the beam, GapIntegral).
  double Gap(const Point& point, const Eigen::VectorXd& d) const {
    const double gap = point.gap_m + Along(point, d) * length_m_;
    return gap < separation_m_ ? separation_m_ : gap;
  }
  /// Whether a gap Gap() gave [m] is the separation holding it: the pressure is constant there.
  bool Held(double gap_m) const { return separation_m_ > 0.0 && gap_m <= separation_m_; }
  /// The point's motion toward +y per unit of the vector x (a displacement or a velocity),
  /// in x's internal units.
  static double Along(const Point& point, const Eigen::VectorXd& x) { return point.Dot(x); }

 private:
  // How far below a member's axis its lower face lies, and how wide the face is seen from below,
  // for the section turned about the axis so that its thickness direction has the global y
  // component a1 and its width direction a2.
  struct Face {
    double depth = 0.0;
    double width = 0.0;
  };
  Face MemberFace(int e) const {
    const Eigen::Matrix3d& axes = model_.mesh().elements[e].axes;
    const RectangularSection& s =
        model_.description().members[model_.mesh().elements[e].member].section;
    const double a1 = std::abs(axes(1, 1)), a2 = std::abs(axes(2, 1));
    return {0.5 * (a1 * s.thickness + a2 * s.width), a1 * s.width + a2 * s.thickness};
  }

  // The y of the structure's lowest face at rest [m].
  double LowestFace() const {
    double lowest = std::numeric_limits<double>::infinity();
    const FrameMesh& mesh = model_.mesh();
    for (int e = 0; e < model_.ElementCount(); ++e) {
      const double depth = MemberFace(e).depth;
      lowest = std::min({lowest, mesh.nodes[mesh.elements[e].from].position.y() - depth,
                         mesh.nodes[mesh.elements[e].to].position.y() - depth});
    }
    for (const StructureBody& body : model_.description().bodies) {
      lowest = std::min(lowest, body.center.y() - 0.5 * body.size.y());
    }
    return lowest;
  }

  void PlaceOnElement(int e, const Electrode& electrode, const GaussLegendre& rule) {
    const FrameMesh::Element& element = model_.mesh().elements[e];
    if (std::abs(element.axes(0, 1)) > 1e-9) return;  // not parallel to the substrate
    const Eigen::Vector3d a = model_.mesh().nodes[element.from].position;
    const Eigen::Vector3d b = model_.mesh().nodes[element.to].position;
    // The part of xi in [0, 1] whose axis point lies over the electrode.
    double lo = 0.0, hi = 1.0;
    const double start[2] = {a.x(), a.z()}, step[2] = {b.x() - a.x(), b.z() - a.z()};
    const std::array<double, 2>* bounds[2] = {&electrode.x, &electrode.z};
    for (int k = 0; k < 2; ++k) {
      if (step[k] == 0.0) {
        if (start[k] < (*bounds[k])[0] || start[k] > (*bounds[k])[1]) return;
        continue;
      }
      const double t0 = ((*bounds[k])[0] - start[k]) / step[k];
      const double t1 = ((*bounds[k])[1] - start[k]) / step[k];
      lo = std::max(lo, std::min(t0, t1));
      hi = std::min(hi, std::max(t0, t1));
    }
    if (!(hi > lo)) return;
    const Face face = MemberFace(e);
    const double a1 = element.axes(1, 1), a2 = element.axes(2, 1);
    const double l = model_.elements()[e].properties().length;
    for (std::size_t k = 0; k < rule.points.size(); ++k) {
      const double xi = lo + rule.points[k] * (hi - lo);
      const std::array<double, 4> h = HermiteShapes(xi);
      Point point;
      point.local[1] = a1 * h[0];
      point.local[5] = a1 * l * h[1];
      point.local[7] = a1 * h[2];
      point.local[11] = a1 * l * h[3];
      point.local[2] = a2 * h[0];
      point.local[4] = -a2 * l * h[1];
      point.local[8] = a2 * h[2];
      point.local[10] = -a2 * l * h[3];
      point.Set(model_.ElementDofs(e), model_.ElementTransform(e).transpose() * point.local);
      point.gap_m = (a + xi * (b - a)).y() - face.depth - substrate_m_;
      point.area_m2 = rule.weights[k] * (hi - lo) * element.length * face.width;
      point.width_m = face.width;
      points_.push_back(point);
    }
  }

  void PlaceOnBody(int body, const Electrode& electrode, const GaussLegendre& rule) {
    const StructureBody& b = model_.description().bodies[body];
    const Eigen::Vector3d& c = b.center;
    const auto clip = electrode.Clip({c.x() - 0.5 * b.size.x(), c.x() + 0.5 * b.size.x()},
                                     {c.z() - 0.5 * b.size.z(), c.z() + 0.5 * b.size.z()});
    if (!(clip[0][1] > clip[0][0] && clip[1][1] > clip[1][0])) return;
    const int carrier = model_.mesh().body_carrier[body];
    std::array<int, 12> dofs;
    dofs.fill(-1);
    dofs[0] = model_.CarrierDof(carrier, 1);
    dofs[1] = model_.CarrierDof(carrier, 3);
    dofs[2] = model_.CarrierDof(carrier, 5);
    for (std::size_t i = 0; i < rule.points.size(); ++i) {
      for (std::size_t j = 0; j < rule.points.size(); ++j) {
        const double x = clip[0][0] + rule.points[i] * (clip[0][1] - clip[0][0]);
        const double z = clip[1][0] + rule.points[j] * (clip[1][1] - clip[1][0]);
        FrameModel::ElementVector n = FrameModel::ElementVector::Zero();
        n[0] = 1.0;                       // u_y
        n[1] = -(z - c.z()) / length_m_;  // theta_x
        n[2] = (x - c.x()) / length_m_;   // theta_z
        Point point;
        point.Set(dofs, n);
        point.gap_m = c.y() - 0.5 * b.size.y() - substrate_m_;
        point.area_m2 = rule.weights[i] * rule.weights[j] * (clip[0][1] - clip[0][0]) *
                        (clip[1][1] - clip[1][0]);
        point.width_m = std::min(b.size.x(), b.size.z());
        points_.push_back(point);
      }
    }
  }

  const FrameModel& model_;
  double length_m_;  ///< metres per internal length unit
  double substrate_m_ = 0.0;
  double separation_m_ = 0.0;
  std::vector<Point> points_;
  std::vector<int> first_point_;
};

}  // namespace cosmems
