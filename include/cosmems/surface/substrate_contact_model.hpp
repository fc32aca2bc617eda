#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_cholesky.hpp"

namespace cosmems {

struct ContactOptions {
  double gap = 0.0;  ///< m, from the beam's undeformed lower face to the substrate
  /// m: how close the faces come in contact (asperities, a native oxide). Keeps the surface
  /// pressures, which grow without bound as the gap closes, finite on a beam lying down.
  double separation = 0.0;
  bool stiction = false;
  double adhesion_energy = 0.0;  ///< work of adhesion Gamma [J/m^2], with stiction
  double proximity = 0.0;        ///< m: a local gap below this is "near"; 0: a tenth of the gap
  double tolerance = 0.0;        ///< m: the penetration accepted; 0: 1e-4 of the gap
  /// The augmented-Lagrangian penalty per node, relative to the beam's largest u_y stiffness.
  double penalty = 1e4;
};

/// What the substrate contact of one beam never changes while it runs: the points it holds, their
/// shapes, the gap, tolerance, proximity and penalty in internal units, and the factor of the mass
/// matrix that the impact projection solves with (SubstrateContact). Built once, it is read-only,
/// so any number of contacts (a haptic session and a sweep's samples, on any threads) can share
/// one through a shared_ptr while each keeps its own multipliers, stuck flags and events. The beam
/// model must outlive it.
template <int Dim>
class SubstrateContactModel {
 public:
  /// A point the constraint holds: g = gap + shape . d[dof]. The nodes' first (u_y alone), then
  /// those inside the elements that can touch (the Hermite cubic of u_y and h theta_z at a fixed
  /// xi).
  struct Point {
    std::array<int, 4> dof{-1, -1, -1, -1};  ///< reduced indices (-1: supported)
    std::array<double, 4> shape{};
    int node = -1;       ///< node number along the beam (nodes)
    double x = 0.0;      ///< internal units (nodes; an element's first node for its points)
    double width = 0.0;  ///< internal units (nodes)
    double h = 0.0;      ///< the element's length, internal units (elements)
    std::array<int, 2> ends{-1, -1};  ///< the element's nodes' points (-1: a support)
    int slope = -1;  ///< a free end's theta_z (reduced; -1: not an end, or its rotation held)
    /// shape and dof with the supported entries as weight 0 on index 0: Along() without a branch
    std::array<int, 4> gather{0, 0, 0, 0};
    std::array<double, 4> weight{};
  };

  /// Where an element is held between its nodes: its quarter points. A point held fixed never
  /// moves its multiplier to where it does not belong (a point following the cubic's deepest place
  /// pushed the element down elsewhere, and the stuck cantilever's release never settled).
  static constexpr std::array<double, 3> kInnerPoints = {0.25, 0.5, 0.75};

  SubstrateContactModel(const BeamModel<Dim>& model, const ContactOptions& options)
      : stiffness_(model.Stiffness()), units_(model.units()), options_(options) {
    RequirePositive("gap", options.gap);
    RequireWithin("separation", options.separation, 0.0, 0.5 * options.gap);
    if (options.stiction) RequirePositive("adhesion_energy", options.adhesion_energy);
    constexpr double kLargest = std::numeric_limits<double>::max();
    RequireWithin("proximity", options.proximity, 0.0, kLargest);
    RequireWithin("tolerance", options.tolerance, 0.0, kLargest);
    RequireWithin("penalty", options.penalty, 10.0, 1e8);
    const UnitSystem& u = model.units();
    gap_ = (options.gap - options.separation) / u.length;
    tolerance_ = (options.tolerance > 0.0 ? options.tolerance : 1e-4 * options.gap) / u.length;
    proximity_ = (options.proximity > 0.0 ? options.proximity : 0.1 * options.gap) / u.length;
    double largest = 0.0;
    std::vector<int> point_of_node(static_cast<std::size_t>(model.NodeCount()), -1);
    for (int node = 0; node < model.NodeCount(); ++node) {
      const int w = model.dofs().Reduced(node, NodalDof::kUy);
      if (w < 0) continue;  // a support never reaches the substrate
      point_of_node[static_cast<std::size_t>(node)] = static_cast<int>(points_.size());
      const int e = std::min(node, model.ElementCount() - 1);
      Point point;
      point.dof[0] = w;
      point.shape[0] = 1.0;
      point.node = node;
      point.x = model.NodeX()[node];
      point.width = model.description().elements[e].section.width / u.length;
      const bool end = node == 0 || node == model.NodeCount() - 1;
      point.slope = end ? model.dofs().Reduced(node, NodalDof::kRz) : -1;
      points_.push_back(point);
      largest = std::max(largest, stiffness_(w, w));
    }
    node_count_ = points_.size();
    for (int e = 0; e < model.ElementCount(); ++e) {
      Point point;
      for (int node = 0; node < 2; ++node) {
        point.dof[2 * node] = model.dofs().Reduced(e + node, NodalDof::kUy);
        point.dof[2 * node + 1] = model.dofs().Reduced(e + node, NodalDof::kRz);
      }
      if (point.dof[0] < 0 && point.dof[2] < 0) continue;  // between two supports
      point.h = model.elements()[e].properties().length;
      point.x = model.NodeX()[e];
      point.ends = {point_of_node[static_cast<std::size_t>(e)],
                    point_of_node[static_cast<std::size_t>(e) + 1]};
      for (double xi : kInnerPoints) {
        const std::array<double, 4> n = HermiteShapes(xi);
        point.shape = {n[0], point.h * n[1], n[2], point.h * n[3]};
        points_.push_back(point);
      }
    }
    for (Point& point : points_) {
      for (int a = 0; a < 4; ++a) {
        point.gather[a] = std::max(point.dof[a], 0);
        point.weight[a] = point.dof[a] >= 0 ? point.shape[a] : 0.0;
      }
      reach_ = std::max(reach_, std::abs(point.weight[0]) + std::abs(point.weight[1]) +
                                    std::abs(point.weight[2]) + std::abs(point.weight[3]));
    }
    penalty_ = options.penalty * largest;
    length_ = model.NodeX().back();
    mass_factor_.Compute(model.Mass(0));
  }

  /// Every point, the nodes' first (NodeCount() of them), then the elements' inner points.
  const std::vector<Point>& points() const { return points_; }
  /// The number of nodes that can touch (the free ones), from the first support on.
  std::size_t node_count() const { return node_count_; }
  /// The beam's stiffness K (reduced, internal units), the compliance's base.
  const SymmetricBandMatrix& stiffness() const { return stiffness_; }
  /// The factor of the mass matrix M(0), for the impact projection.
  const BandCholesky& mass_factor() const { return mass_factor_; }
  const UnitSystem& units() const { return units_; }
  const ContactOptions& options() const { return options_; }
  /// Internal units: the gap to the contact plane, the penetration accepted, the proximity
  /// warning's distance, the penalty k, the beam's length.
  double gap() const { return gap_; }
  double tolerance() const { return tolerance_; }
  double proximity() const { return proximity_; }
  double penalty() const { return penalty_; }
  double length() const { return length_; }
  /// No point's gap differs from gap() by more than reach() max_i |d_i| (the largest sum of a
  /// point's |weights|): one pass over d bounds every gap, without visiting the points.
  double reach() const { return reach_; }

  /// shape . x[dof] for a point, the supported entries left out (as weight 0).
  static double Along(const Point& point, const Eigen::Ref<const Eigen::VectorXd>& x) {
    double sum = 0.0;
    for (int a = 0; a < 4; ++a) sum += point.weight[a] * x[point.gather[a]];
    return sum;
  }
  /// The local gap to the contact plane at a point, for the displacement d (internal units).
  double Gap(const Point& point, const Eigen::VectorXd& d) const { return gap_ + Along(point, d); }

  /// The gap where an element's cubic (that of any of its points) comes nearest the substrate
  /// inside the element; +inf when the cubic has no minimum there (the nodes hold its ends).
  double DeepestGap(const Point& point, const Eigen::VectorXd& d) const {
    std::array<double, 4> q{};  // w1, h theta1, w2, h theta2
    for (int a = 0; a < 4; ++a) {
      if (point.dof[a] >= 0) q[a] = (a % 2 ? point.h : 1.0) * d[point.dof[a]];
    }
    // dw/dxi = A xi^2 + B xi + C, from the Hermite cubics' derivatives.
    const double A = 6.0 * q[0] + 3.0 * q[1] - 6.0 * q[2] + 3.0 * q[3];
    const double B = -6.0 * q[0] - 4.0 * q[1] + 6.0 * q[2] - 2.0 * q[3];
    const double C = q[1];
    double best = std::numeric_limits<double>::infinity();
    auto consider = [&](double xi) {
      if (!(xi > 0.0 && xi < 1.0) || 2.0 * A * xi + B <= 0.0) return;  // not an inner minimum
      const std::array<double, 4> n = HermiteShapes(xi);
      best = std::min(best, gap_ + n[0] * q[0] + n[1] * q[1] + n[2] * q[2] + n[3] * q[3]);
    };
    if (A == 0.0) {
      if (B != 0.0) consider(-C / B);
      return best;
    }
    const double discriminant = B * B - 4.0 * A * C;
    if (discriminant < 0.0) return best;
    // The roots without cancellation.
    const double t = -0.5 * (B + std::copysign(std::sqrt(discriminant), B));
    if (t != 0.0) consider(C / t);
    consider(t / A);
    return best;
  }

  /// Whether node points a and b are neighbours along the beam.
  bool Adjacent(std::size_t a, std::size_t b) const {
    return points_[b].node == points_[a].node + 1;
  }

  /// k as a node's point, or std::out_of_range.
  std::size_t Checked(int k) const {
    if (k < 0 || static_cast<std::size_t>(k) >= node_count_) {
      throw std::out_of_range("contact node " + std::to_string(k) + " of " +
                              std::to_string(node_count_));
    }
    return static_cast<std::size_t>(k);
  }

  /// The displacement with every free node on the contact plane and flat (internal units): the
  /// beam pressed down all along, a start for the solvers. The nodes sit the tolerance deep, so
  /// that the contact holds them from the first iteration on (a node exactly on the plane is not
  /// pressed, and a surface pressure alone would make the first Newton matrix indefinite).
  Eigen::VectorXd PressedDisplacement() const {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(stiffness_.size());
    for (std::size_t k = 0; k < node_count_; ++k) d[points_[k].dof[0]] = -gap_ - tolerance_;
    return d;
  }

  /// The largest penetration of the contact plane anywhere along the beam at d [m] (0 when none):
  /// at the nodes and at the deepest point of each element's cubic.
  double Penetration(const Eigen::VectorXd& d) const {
    double deepest = 0.0;
    for (std::size_t k = 0; k < node_count_; ++k) deepest = std::max(deepest, -Gap(points_[k], d));
    // One cubic per element: its first point's.
    for (std::size_t k = node_count_; k < points_.size(); k += kInnerPoints.size()) {
      deepest = std::max(deepest, -DeepestGap(points_[k], d));
    }
    return deepest * units_.length;
  }

 private:
  const SymmetricBandMatrix& stiffness_;
  UnitSystem units_;
  ContactOptions options_;
  double gap_ = 0.0, tolerance_ = 0.0, proximity_ = 0.0, penalty_ = 0.0, length_ = 0.0;
  double reach_ = 0.0;
  std::vector<Point> points_;
  std::size_t node_count_ = 0;  ///< the nodes' points, first in points_
  BandCholesky mass_factor_;
};

}  // namespace cosmems
