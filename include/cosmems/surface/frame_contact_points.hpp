#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/structure/dof_weights.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_faces.hpp"

namespace cosmems {

/// Where a frame's faces can touch the substrate first (FrameFaces under one electrode that
/// covers everything): each member element's nodes and quarter points on its lower face's centre
/// line (the element's end only at its member's last element, so a node is held once), each
/// body's four lower corners (a rigid plate's lowest points, however it tilts). Each point has
/// its gap at rest and how far it moves toward +y per unit of each degree of freedom it depends
/// on; the members' points come first, element by element, then the bodies'. The substrate
/// contact's candidates (FrameSubstrateContact, FrameAdhesionSites).
class FrameContactPoints {
 public:
  /// Its weights are its motion toward +y.
  struct Point : DofWeights {
    double gap_m = 0.0;    ///< at rest
    double width_m = 0.0;  ///< the strip's width, or a plate's narrower side
    /// on a member, the local u_y weights of its element (for the element's share)
    FrameModel::ElementVector local = FrameModel::ElementVector::Zero();
  };

  /// Throws std::invalid_argument for a gap that is not positive.
  FrameContactPoints(const FrameModel& model, double gap) : faces_(model, gap, {Electrode{}}) {
    static constexpr std::array<double, 4> kAlong = {0.0, 0.25, 0.5, 0.75};
    const std::vector<FrameMesh::Element>& elements = model.mesh().elements;
    const std::vector<FrameFaces::Strip>& strips = faces_.strips();
    std::size_t strip = 0;
    first_point_.push_back(0);
    for (int e = 0; e < model.ElementCount(); ++e) {
      const bool member_ends =
          e + 1 == model.ElementCount() || elements[e + 1].member != elements[e].member;
      for (; strip < strips.size() && strips[strip].element == e; ++strip) {
        for (const double xi : kAlong) Place(model, strips[strip], xi);
        if (member_ends) Place(model, strips[strip], 1.0);
      }
      first_point_.push_back(static_cast<int>(points_.size()));
    }
    for (const FrameFaces::Plate& plate : faces_.plates()) {
      for (const double x : plate.x) {
        for (const double z : plate.z) {
          Point point;
          point.Set(plate.dofs, faces_.PlateWeights(x, z));
          point.gap_m = plate.gap_m;
          point.width_m = plate.width_m;
          points_.push_back(point);
        }
      }
    }
  }

  const std::vector<Point>& points() const { return points_; }
  /// Element e's points: [first(e), first(e + 1)); first(ElementCount()) ends the members'.
  int first(int e) const { return first_point_[e]; }
  /// The point's motion toward +y per unit of the vector x (a displacement or a velocity),
  /// in x's internal units.
  static double Along(const Point& point, const Eigen::VectorXd& x) { return point.Dot(x); }

 private:
  void Place(const FrameModel& model, const FrameFaces::Strip& strip, double xi) {
    const std::array<double, 4> h = HermiteShapes(xi);
    Point point;
    point.local = faces_.StripLocal(strip, h);
    point.Set(model.ElementDofs(strip.element), faces_.StripWeights(strip, h));
    point.gap_m = strip.gap_m;
    point.width_m = strip.width_m;
    points_.push_back(point);
  }

  FrameFaces faces_;
  std::vector<Point> points_;
  std::vector<int> first_point_;
};

}  // namespace cosmems
