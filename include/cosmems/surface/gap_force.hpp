#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/core/gauss_legendre.hpp"
#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Where a gap pressure acts: the substrate at `gap` [m] below the beam's undeformed lower face,
/// over [start, end] [m] along the beam (an electrode's extent; the whole beam for surface
/// forces). The pressure is integrated by `points` Gauss-Legendre points on each interval of a
/// subdivision that adapts to the gap (see GapForce).
struct GapSpan {
  double gap = 0.0;
  double start = 0.0;
  double end = 0.0;
  int points = 4;
  /// An interval is halved until its largest gap is at most this multiple of its smallest.
  double gap_ratio = 1.25;
};

/// A gap pressure p(d) (see gap_pressures.hpp) pulling the beam toward the substrate, as a
/// NonlinearForce: with d(x) = gap + w(x) the local gap (w = u_y of the axis, negative toward
/// the substrate) and b the width,
///   r(d) = int N_w^T b p(gap + w) dx,   dr/dd = int N_w^T b p'(gap + w) N_w dx,
/// N_w the Hermite shape functions of u_y (the static ones: the power-series terms are
/// frequency corrections). p' < 0: the tangent softens the beam, which is what makes it pull in.
///
/// Quadrature: p grows like 1/d^n, so where the beam nears the substrate it varies over lengths
/// of order d / |w'|, far shorter than an element. A fixed rule per element loses accuracy
/// there (the reference cantilever with 1 % of its gap left at the tip, Casimir: 5 % error with
/// 8 points per element, 1e-4 with 16). Each element (its part inside the span) is therefore
/// halved, recursively, until the gap varies by at most GapSpan::gap_ratio over each interval
/// (judged at its ends and midpoint), and each interval gets the Gauss rule: the error then no
/// longer depends on how close the substrate is (the defaults: 2e-7 of the force at half the
/// gap, 8e-9 and 2e-9 with 1 % and 1e-4 of it left). A state whose
/// gap closes anywhere (d <= 0) is outside the force's domain: Evaluate() returns false.
/// Evaluate() allocates nothing.
template <int Dim, typename Pressure>
class GapForce final : public NonlinearForce {
 public:
  GapForce(const BeamModel<Dim>& model, Pressure pressure, const GapSpan& span)
      : pressure_(pressure),
        length_(model.units().length),
        ratio_(span.gap_ratio),
        rule_(GaussLegendre::Of(span.points)) {
    const UnitSystem& u = model.units();
    RequirePositive("gap", span.gap);
    RequireWithin("gap_ratio", span.gap_ratio, 1.01, 100.0);
    const double length = model.description().Length();
    RequireWithin("electrode_start", span.start, 0.0, length);
    RequireWithin("electrode_end", span.end, span.start, length);
    gap_ = span.gap / u.length;
    for (int e = 0; e < model.ElementCount(); ++e) {
      const double h = model.elements()[e].properties().length;
      const double x0 = model.NodeX()[e] * u.length;
      const double a = std::max(x0, span.start), b = std::min(x0 + h * u.length, span.end);
      if (b <= a) continue;
      Segment segment;
      segment.h = h;
      segment.xi_start = (a - x0) / (h * u.length);
      segment.xi_end = (b - x0) / (h * u.length);
      // Internal force per internal length per pascal.
      segment.weight = h * model.description().elements[e].section.width / u.ForcePerLength();
      for (int node = 0; node < 2; ++node) {
        segment.dof[2 * node] = model.ElementDof(e, Index(node, NodalDof::kUy));
        segment.dof[2 * node + 1] = model.ElementDof(e, Index(node, NodalDof::kRz));
      }
      segments_.push_back(segment);
    }
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (const Segment& s : segments_) {
      std::array<double, 4> q{};  // the element's u_y, h theta_z values
      for (int a = 0; a < 4; ++a) {
        if (s.dof[a] >= 0) q[a] = (a % 2 ? s.h : 1.0) * d[s.dof[a]];
      }
      // Depth-first halving with a fixed stack: 2^-40 of an element is far below any gap ratio.
      std::array<std::pair<double, double>, 48> stack;
      int top = 0;
      stack[top++] = {s.xi_start, s.xi_end};
      while (top > 0) {
        const auto [a, b] = stack[--top];
        const double ga = Gap(q, a), gm = Gap(q, 0.5 * (a + b)), gb = Gap(q, b);
        const double low = std::min({ga, gm, gb}), high = std::max({ga, gm, gb});
        if (!(low > 0.0)) return false;  // closed, or not finite
        if (high > ratio_ * low && top + 2 <= static_cast<int>(stack.size())) {
          stack[top++] = {0.5 * (a + b), b};
          stack[top++] = {a, 0.5 * (a + b)};
          continue;
        }
        Integrate(s, q, a, b, force, tangent);
      }
    }
    return true;
  }

  const Pressure& pressure() const { return pressure_; }
  Pressure& pressure() { return pressure_; }

 private:
  struct Segment {
    std::array<int, 4> dof{};  ///< reduced u_y, theta_z of both nodes (-1: supported)
    double h = 0.0;            ///< element length
    double xi_start = 0.0, xi_end = 1.0;
    double weight = 0.0;
  };

  static int Index(int node, NodalDof dof) {
    return node * FrameLayout<Dim>::kNodeDofs + FrameLayout<Dim>::kIndex[static_cast<int>(dof)];
  }

  double Gap(const std::array<double, 4>& q, double xi) const {
    const std::array<double, 4> n = HermiteShapes(xi);
    return gap_ + n[0] * q[0] + n[1] * q[1] + n[2] * q[2] + n[3] * q[3];
  }

  void Integrate(const Segment& s, const std::array<double, 4>& q, double a, double b,
                 Eigen::VectorXd& force, ForceTangent& tangent) const {
    for (std::size_t k = 0; k < rule_.points.size(); ++k) {
      const double xi = a + rule_.points[k] * (b - a);
      std::array<double, 4> n = HermiteShapes(xi);
      n[1] *= s.h;
      n[3] *= s.h;
      const double gap = Gap(q, xi) * length_;  // m
      const double w = rule_.weights[k] * (b - a) * s.weight;
      const double p = w * pressure_.Value(gap);
      const double dp = w * pressure_.Slope(gap) * length_;
      for (int i = 0; i < 4; ++i) {
        if (s.dof[i] < 0) continue;
        force[s.dof[i]] += n[i] * p;
        for (int j = i; j < 4; ++j) {
          if (s.dof[j] >= 0) tangent.band().Add(s.dof[i], s.dof[j], dp * n[i] * n[j]);
        }
      }
    }
  }

  Pressure pressure_;
  double length_;  ///< m per internal length unit
  double ratio_;
  GaussLegendre rule_;
  double gap_ = 0.0;  ///< internal units
  std::vector<Segment> segments_;
};

}  // namespace cosmems
