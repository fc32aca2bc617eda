#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/core/validation.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/electrode.hpp"

namespace cosmems {

/// Where a force across the gap acts on a frame: the substrate plane `gap` below the structure's
/// lowest face at rest, and the electrodes on it (by default one under all of the structure).
struct FrameGapOptions {
  double gap = 0.0;  ///< m
  std::vector<Electrode> electrodes = {Electrode{}};
  /// Gauss-Legendre points along each element's part over an electrode, and along each side of
  /// a body's rectangle over one (on each interval of the gap's subdivision, FrameGapIntegral).
  int points = 4;
  /// m: the contact plane's height above the substrate when the scene has contact, which holds
  /// the gap from below, as on the beam (GapSpan::separation); 0: no contact.
  double separation = 0.0;
  /// FrameGapIntegral halves a face until its largest gap is at most this multiple of its
  /// smallest (as GapSpan::gap_ratio on the beam).
  double gap_ratio = 1.25;
  /// Whether the bodies' plates are integrated (the squeeze film has a plate law of its own).
  bool plates = true;
};

/// The lower faces of a frame over the electrodes of the substrate, the geometry the forces
/// across the gap share (FrameGapIntegral, FrameContactPoints).
///
/// A member element parallel to the substrate is a strip as wide as its section seen from below;
/// its deflection toward the substrate is the Hermite cubic of its element (the static shape, as
/// on the beam), its part over an electrode clipped where its axis crosses the electrode's edges.
/// A member that is not parallel to the substrate shows it only an end, and has no strip. A body
/// is a plate, its lower face at g_0 + u_y + theta_z (x - x_c) - theta_x (z - z_c), its rectangle
/// clipped by each electrode. Strips come element by element (each element's electrodes in
/// their order), then the plates body by body.
class FrameFaces {
 public:
  /// A member element's lower face over one electrode: its axis over xi in [lo, hi].
  struct Strip {
    int element = 0;
    double lo = 0.0, hi = 1.0;
    double gap_m = 0.0;     ///< at rest
    double width_m = 0.0;   ///< seen from below
    double length_m = 0.0;  ///< the element's
  };
  /// A body's lower face over one electrode: x in [x[0], x[1]], z in [z[0], z[1]] from the body's
  /// centre [m].
  struct Plate {
    int body = 0;
    std::array<double, 2> x{}, z{};
    double gap_m = 0.0;    ///< at rest
    double width_m = 0.0;  ///< the body's narrower side
    /// Its carrier's u_y, theta_x and theta_z degrees of freedom (-1: held), then -1.
    std::array<int, 12> dofs{};
  };

  /// Throws std::invalid_argument for a gap that is not positive, an electrode that is empty or
  /// two electrodes that overlap (a force would count twice where they do).
  FrameFaces(const FrameModel& model, double gap, const std::vector<Electrode>& electrodes)
      : model_(model), length_m_(model.units().length) {
    RequirePositive("gap", gap);
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
    substrate_m_ = LowestFace() - gap;
    for (int e = 0; e < model.ElementCount(); ++e) {
      for (const Electrode& electrode : electrodes) ClipElement(e, electrode);
    }
    for (std::size_t b = 0; b < model.description().bodies.size(); ++b) {
      for (const Electrode& electrode : electrodes) ClipBody(static_cast<int>(b), electrode);
    }
  }

  const std::vector<Strip>& strips() const { return strips_; }
  const std::vector<Plate>& plates() const { return plates_; }
  /// The substrate plane's y [m].
  double substrate_m() const { return substrate_m_; }
  /// metres per internal length unit
  double length_m() const { return length_m_; }

  /// The strip's motion toward +y in its element's local degrees of freedom, at the point whose
  /// Hermite values (HermiteShapes) are h.
  FrameModel::ElementVector StripLocal(const Strip& strip, const std::array<double, 4>& h) const {
    const Eigen::Matrix3d& axes = model_.mesh().elements[strip.element].axes;
    const double a1 = axes(1, 1), a2 = axes(2, 1);
    const double l = model_.elements()[strip.element].properties().length;
    FrameModel::ElementVector local = FrameModel::ElementVector::Zero();
    local[1] = a1 * h[0];
    local[5] = a1 * l * h[1];
    local[7] = a1 * h[2];
    local[11] = a1 * l * h[3];
    local[2] = a2 * h[0];
    local[4] = -a2 * l * h[1];
    local[8] = a2 * h[2];
    local[10] = -a2 * l * h[3];
    return local;
  }
  /// The strip's motion toward +y per unit of each of its element's degrees of freedom
  /// (model.ElementDofs) at the same point.
  FrameModel::ElementVector StripWeights(const Strip& strip, const std::array<double, 4>& h) const {
    return model_.ElementTransform(strip.element).transpose() * StripLocal(strip, h);
  }
  /// The plate's motion toward +y per unit of its carrier's u_y, theta_x and theta_z (Plate::dofs)
  /// at (x, z) [m] from the body's centre.
  FrameModel::ElementVector PlateWeights(double x, double z) const {
    FrameModel::ElementVector n = FrameModel::ElementVector::Zero();
    n[0] = 1.0;
    n[1] = -z / length_m_;
    n[2] = x / length_m_;
    return n;
  }

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

  void ClipElement(int e, const Electrode& electrode) {
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
    // Parallel to the substrate: the axis keeps one height along the element.
    strips_.push_back({e, lo, hi, a.y() - face.depth - substrate_m_, face.width, element.length});
  }

  void ClipBody(int body, const Electrode& electrode) {
    const StructureBody& b = model_.description().bodies[body];
    const Eigen::Vector3d& c = b.center;
    const auto clip = electrode.Clip({c.x() - 0.5 * b.size.x(), c.x() + 0.5 * b.size.x()},
                                     {c.z() - 0.5 * b.size.z(), c.z() + 0.5 * b.size.z()});
    if (!(clip[0][1] > clip[0][0] && clip[1][1] > clip[1][0])) return;
    const int carrier = model_.mesh().body_carrier[body];
    Plate plate;
    plate.body = body;
    plate.x = {clip[0][0] - c.x(), clip[0][1] - c.x()};
    plate.z = {clip[1][0] - c.z(), clip[1][1] - c.z()};
    plate.gap_m = c.y() - 0.5 * b.size.y() - substrate_m_;
    plate.width_m = std::min(b.size.x(), b.size.z());
    plate.dofs.fill(-1);
    plate.dofs[0] = model_.CarrierDof(carrier, 1);
    plate.dofs[1] = model_.CarrierDof(carrier, 3);
    plate.dofs[2] = model_.CarrierDof(carrier, 5);
    plates_.push_back(plate);
  }

  const FrameModel& model_;
  double length_m_;  ///< metres per internal length unit
  double substrate_m_ = 0.0;
  std::vector<Strip> strips_;
  std::vector<Plate> plates_;
};

}  // namespace cosmems
