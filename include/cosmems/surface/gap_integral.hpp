#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/core/gauss_legendre.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// Where a gap effect acts: the substrate at `gap` [m] below the beam's undeformed lower face,
/// over [start, end] [m] along the beam (an electrode's extent; the whole beam for surface
/// forces and gas films). It is integrated by `points` Gauss-Legendre points on each interval of
/// a subdivision that adapts to the gap (see GapIntegral).
struct GapSpan {
  double gap = 0.0;
  double start = 0.0;
  double end = 0.0;
  int points = 4;
  /// An interval is halved until its largest gap is at most this multiple of its smallest.
  double gap_ratio = 1.25;
  /// m: where contact is declared, how close the faces come (ContactOptions::separation). Nearer
  /// than this the effect sees this gap: what lies below the contact plane is the penetration the
  /// contact's penalty allows while Newton iterates, not an approach, and a pressure growing like
  /// 1/d^n through it would outgrow the penalty's stiffness and turn each iterate that touches
  /// into one that lifts off (the reference cantilever's tip, pressed onto the substrate with the
  /// Casimir force at 20 nm, cycled so at every cut of its step). 0: no contact, the gap closes.
  double separation = 0.0;

  /// This span with contact stopping the faces at `separation_m`.
  GapSpan WithSeparation(double separation_m) const {
    GapSpan out = *this;
    out.separation = separation_m;
    return out;
  }
};

/// The quadrature of an effect that depends on the local gap d(x) = gap + w(x) (w = u_y of the
/// axis, negative toward the substrate, interpolated by the Hermite cubics of each element):
/// Integrate() calls the effect at every quadrature point of the span with the point's shape
/// functions N_w (u_y and h theta_z of both nodes), its gap and its weight.
///
/// Such effects grow like 1/d^n, so where the beam nears the substrate they vary over lengths of
/// order d / |w'|, far shorter than an element. A fixed rule per element loses accuracy there
/// (the reference cantilever with 1 % of its gap left at the tip, Casimir: 5 % error with 8
/// points per element, 1e-4 with 16). Each element (its part inside the span) is therefore
/// halved, recursively, until the gap varies by at most GapSpan::gap_ratio over each interval
/// (judged at its ends and midpoint), and each interval gets the Gauss rule: the error then no
/// longer depends on how close the substrate is (the defaults: 2e-7 of the Casimir force at half
/// the gap, 8e-9 and 2e-9 with 1 % and 1e-4 of it left). The gap is held at GapSpan::separation
/// from below (Held()); without it, a state whose gap closes anywhere (d <= 0) is outside the
/// effect's domain: Integrate() returns false. Allocates nothing.
template <int Dim>
class GapIntegral {
 public:
  /// An element's part inside the span.
  struct Segment {
    std::array<int, 4> dof{};  ///< reduced u_y, theta_z of both nodes (-1: supported)
    double h = 0.0;            ///< element length, internal units
    double xi_start = 0.0, xi_end = 1.0;
    double width_m = 0.0;  ///< the section's width
    /// Internal force per unit of line load [N/m] and of the element's coordinate xi.
    double weight = 0.0;
  };

  GapIntegral(const BeamModel<Dim>& model, const GapSpan& span)
      : length_m_(model.units().length),
        ratio_(span.gap_ratio),
        rule_(GaussLegendre::Of(span.points)) {
    const UnitSystem& u = model.units();
    RequirePositive("gap", span.gap);
    RequireWithin("gap_ratio", span.gap_ratio, 1.01, 100.0);
    // The element lengths sum to the beam's length only to round-off (13 elements of 200 um end
    // 8e-20 m short of it), so a span to the nominal length, as every surface force takes, may
    // end a few ulps past the last node: accepted, as the point loads are (AssembleLoads).
    const double length = model.description().Length() * (1.0 + 1e-12);
    RequireWithin("electrode_start", span.start, 0.0, length);
    RequireWithin("electrode_end", span.end, span.start, length);
    RequireWithin("separation", span.separation, 0.0, 0.5 * span.gap);
    gap_ = span.gap / u.length;
    separation_ = span.separation / u.length;
    for (int e = 0; e < model.ElementCount(); ++e) {
      const double h = model.elements()[e].properties().length;
      const double x0 = model.NodeX()[e] * u.length;
      const double a = std::max(x0, span.start), b = std::min(x0 + h * u.length, span.end);
      if (b <= a) continue;
      Segment segment;
      segment.h = h;
      segment.xi_start = (a - x0) / (h * u.length);
      segment.xi_end = (b - x0) / (h * u.length);
      segment.width_m = model.description().elements[e].section.width;
      segment.weight = h / u.ForcePerLength();
      for (int node = 0; node < 2; ++node) {
        segment.dof[2 * node] = model.dofs().Reduced(e + node, NodalDof::kUy);
        segment.dof[2 * node + 1] = model.dofs().Reduced(e + node, NodalDof::kRz);
      }
      segments_.push_back(segment);
    }
  }

  /// Calls at(segment, N_w, gap [m], weight) at every quadrature point for the state d, the
  /// weight turning a line load [N/m] there into internal force (times N_w). False when the gap
  /// closes or is not finite somewhere.
  template <typename AtPoint>
  bool Integrate(const Eigen::VectorXd& d, AtPoint&& at) const {
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
        for (std::size_t k = 0; k < rule_.points.size(); ++k) {
          const double xi = a + rule_.points[k] * (b - a);
          std::array<double, 4> n = HermiteShapes(xi);
          n[1] *= s.h;
          n[3] *= s.h;
          at(s, n, Gap(q, xi) * length_m_, rule_.weights[k] * (b - a) * s.weight);
        }
      }
    }
    return true;
  }

  /// Metres per internal length unit.
  double length_m() const { return length_m_; }
  /// Whether a gap Integrate() passed [m] is the contact's separation, which holds it from below:
  /// the effect is constant there, its derivative in the displacement zero.
  bool Held(double gap_m) const { return gap_m <= separation_ * length_m_; }

 private:
  // The local gap, at least the separation (NaN stays NaN).
  double Gap(const std::array<double, 4>& q, double xi) const {
    const std::array<double, 4> n = HermiteShapes(xi);
    const double gap = gap_ + n[0] * q[0] + n[1] * q[1] + n[2] * q[2] + n[3] * q[3];
    return gap < separation_ ? separation_ : gap;
  }

  double length_m_;
  double ratio_;
  GaussLegendre rule_;
  double gap_ = 0.0, separation_ = 0.0;  ///< internal units
  std::vector<Segment> segments_;
};

}  // namespace cosmems
