#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "cosmems/structure/dof_weights.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_contact_points.hpp"

namespace cosmems {

/// Where adhesion can hold a device on the substrate, over the contact points of a
/// FrameContactPoints: which points stick, what they hold and how they release
/// (FrameSubstrateContact with stiction).
///
/// A member sticks at its nodes, as the beam does: each node point off a body is a site with its
/// neighbours along the member (the adhered length between two stuck neighbours is the member's
/// width times their distance), and a member's end that nothing else holds (no other member, no
/// body, no support) is a free end, which may stick alone by its edge (the arc-shaped
/// cantilever). The points inside an element only stop it, as do a member's ends on a body while
/// the body is free. A body is a rigid plate: its four corners stick and release together,
/// holding its whole lower face.
class FrameAdhesionSites {
 public:
  /// A member's node point.
  struct Site {
    int point = 0;          ///< its index among the contact points
    int node = 0;           ///< the mesh node
    int member = 0;         ///< the member
    int previous = -1;      ///< the site before it along the member (-1: none)
    int next = -1;          ///< after it
    double s = 0.0;         ///< internal length from the member's first node
    double width = 0.0;     ///< the member's face seen from below (internal length)
    bool free_end = false;  ///< nothing else holds its node
    DofWeights slope;       ///< d/ds of the face's motion toward +y along the member
  };
  /// A body's four lower corners, points [first, first + 4).
  struct Plate {
    int first = 0;
    double area = 0.0;  ///< its lower face (internal length^2)
  };

  FrameAdhesionSites(const FrameModel& model, const FrameContactPoints& points) {
    const double length_m = model.units().length;
    const FrameMesh& mesh = model.mesh();
    const std::size_t count = points.points().size();
    site_of_point_.assign(count, -1);
    held_by_.assign(count, {-1, -1});
    // How many elements meet at each mesh node, and whether a body carries it.
    std::vector<int> degree(mesh.nodes.size(), 0);
    for (const FrameMesh::Element& element : mesh.elements) {
      ++degree[element.from];
      ++degree[element.to];
    }
    auto free_end = [&](int node) {
      const int carrier = mesh.nodes[node].carrier;
      if (degree[node] != 1 || mesh.carriers[carrier].body >= 0) return false;
      for (int d = 0; d < 6; ++d) {  // a planar model has no out-of-plane directions to hold
        if (model.Moves(d) && model.CarrierDof(carrier, d) < 0) return false;
      }
      return true;
    };
    member_length_.assign(model.description().members.size(), 0.0);
    for (int e = 0; e < model.ElementCount(); ++e) {
      const FrameMesh::Element& element = mesh.elements[e];
      const int begin = points.first(e), end = points.first(e + 1);
      const double l = element.length / length_m;
      const double start = member_length_[element.member];
      member_length_[element.member] += l;
      if (begin == end) continue;  // not parallel to the substrate: no points
      const double width = points.points()[begin].width_m / length_m;
      // A node on a body is the plate's edge: the plate's corners hold it, and while they stick
      // it holds nothing (it would hold the plate down beside them, its release counted by none).
      auto body_corner = [&](int node) {
        const int body = mesh.carriers[mesh.nodes[node].carrier].body;
        return body < 0 ? -1 : points.first(model.ElementCount()) + 4 * body;
      };
      const int from = body_corner(element.from) >= 0 ? -1 : begin;
      if (from >= 0)
        AddSite(model, e, 0.0, from, element.from, start, width, free_end(element.from));
      if (from < 0) held_by_[begin] = {body_corner(element.from), -1};
      int to = -1;
      if (end - begin == 5) {  // the member's last element: its far end too
        if (body_corner(element.to) < 0) {
          to = end - 1;
          AddSite(model, e, 1.0, to, element.to, start + l, width, free_end(element.to));
        } else {
          held_by_[end - 1] = {body_corner(element.to), -1};
        }
      } else if (e + 1 < model.ElementCount() && mesh.elements[e + 1].member == element.member) {
        to = end;  // the next element's first point (an interior node): added with it
      }
      for (int k = begin + 1; k < begin + 4; ++k) held_by_[k] = {from, to};
    }
    // Link each member's consecutive sites.
    for (std::size_t i = 1; i < sites_.size(); ++i) {
      Site& a = sites_[i - 1];
      Site& b = sites_[i];
      if (a.member == b.member && b.s > a.s) {
        a.next = static_cast<int>(i);
        b.previous = static_cast<int>(i - 1);
      }
    }
    const int bodies_first = points.first(model.ElementCount());
    for (std::size_t b = 0; b < model.description().bodies.size(); ++b) {
      const Eigen::Vector3d& size = model.description().bodies[b].size;
      const int first = bodies_first + 4 * static_cast<int>(b);
      plates_.push_back({first, size.x() * size.z() / (length_m * length_m)});
      for (int k = first; k < first + 4; ++k) plate_of_point_.push_back(static_cast<int>(b));
    }
  }

  const std::vector<Site>& sites() const { return sites_; }
  const std::vector<Plate>& plates() const { return plates_; }
  /// The site of contact point k, or -1 (an element's inner point, or a body's corner).
  int SiteOf(std::size_t k) const { return k < site_of_point_.size() ? site_of_point_[k] : -1; }
  /// The plate of contact point k, or -1.
  int PlateOf(std::size_t k, std::size_t bodies_first) const {
    return k >= bodies_first ? plate_of_point_[k - bodies_first] : -1;
  }
  /// The contact points whose adhesion idles point k (-1: none): an element's inner point's
  /// element ends, and a member's end on a body that body's first corner.
  const std::array<int, 2>& HeldBy(std::size_t k) const { return held_by_[k]; }
  /// A member's length along its axis (internal).
  double MemberLength(int member) const { return member_length_[member]; }

 private:
  void AddSite(const FrameModel& model, int e, double xi, int point, int node, double s,
               double width, bool free_end) {
    Site site;
    site.point = point;
    site.node = node;
    site.member = model.mesh().elements[e].member;
    site.s = s;
    site.width = width;
    site.free_end = free_end;
    // The face's slope along the axis at an element's end: the Hermite shapes' derivatives there
    // are those of the rotations alone.
    const Eigen::Matrix3d& axes = model.mesh().elements[e].axes;
    FrameModel::ElementVector local = FrameModel::ElementVector::Zero();
    const int at = xi == 0.0 ? 0 : 6;
    local[at + 5] = axes(1, 1);
    local[at + 4] = -axes(2, 1);
    site.slope.Set(model.ElementDofs(e), model.ElementTransform(e).transpose() * local);
    site_of_point_[point] = static_cast<int>(sites_.size());
    sites_.push_back(site);
  }

  std::vector<Site> sites_;
  std::vector<Plate> plates_;
  std::vector<int> site_of_point_;
  std::vector<int> plate_of_point_;
  std::vector<std::array<int, 2>> held_by_;
  std::vector<double> member_length_;
};

}  // namespace cosmems
