#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "cosmems/beam/hermite_shapes.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/gauss_legendre.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/frame_faces.hpp"

namespace cosmems {

/// The quadrature of a pressure p(g) over a frame's faces over the electrodes (FrameFaces), each
/// face subdivided to the gap as the beam's (GapIntegral): pressures that grow like 1/g^n vary,
/// where a face nears the substrate, over lengths of order g / |slope|, far shorter than an
/// element or a plate.
///
/// Each face's gap is g_0 + c . phi, its four coefficients c a fixed linear map B^T d of the
/// displacement: on a strip the Hermite cubic's end values and end slopes times the element's
/// length (phi the Hermite values at xi), on a plate u_y, theta_x and theta_z of its body
/// (phi = 1, -z, x). A strip is halved, recursively, until its largest gap (at its ends and
/// midpoint) is at most FrameGapOptions::gap_ratio times its smallest; a plate's gap is linear,
/// so its extremes are at its corners; where they differ by more than that ratio, it is integrated
/// along its gap's level lines, the range of its gap halved as a strip's. Each interval gets the
/// Gauss rule (a plate within the ratio the tensor rule). The force and tangent gather in c's
/// four coefficients, face by face, and reach the structure's degrees of freedom through B once
/// per face:
///   r = sum over faces B integral phi p(g) dA,   dr/dd = sum B (integral phi p'(g) phi^T dA) B^T.
/// Where a face is halved, the points gather p and p' against polynomials alone (a strip's powers
/// of xi, a level line's cubics of the gap), and phi enters once per strip or piece of the gap's
/// range: the halving's points cost a few multiply-adds besides the pressure.
/// The gap is held at the contact's separation from below, as on the beam. Allocates nothing.
class FrameGapIntegral {
 public:
  /// One face: its coefficients' weights over the degrees of freedom it moves with.
  struct Face {
    bool plate = false;
    int index = 0;  ///< into FrameFaces::strips() or plates()
    int element = -1;
    double gap_m = 0.0;  ///< at rest
    double width_m = 0.0;
    std::array<int, 12> dof{};  ///< the distinct degrees of freedom (count of them)
    int count = 0;
    Eigen::Matrix<double, 12, 4> weights = Eigen::Matrix<double, 12, 4>::Zero();  ///< B's rows
    /// On a strip, its element's local degrees of freedom per coefficient (LocalForce).
    Eigen::Matrix<double, 12, 4> local = Eigen::Matrix<double, 12, 4>::Zero();
  };

  /// Throws std::invalid_argument for the options FrameFaces refuses, or a separation, number of
  /// points or gap ratio out of range.
  FrameGapIntegral(const FrameModel& model, const FrameGapOptions& options)
      : geometry_(model, options.gap, options.electrodes),
        length_m_(model.units().length),
        per_length_m_(1.0 / length_m_),
        ratio_(options.gap_ratio),
        plates_(options.plates),
        rule_(GaussLegendre::Of(options.points)) {
    RequireWithin("separation", options.separation, 0.0, 0.5 * options.gap);
    RequireWithin("gap_ratio", options.gap_ratio, 1.01, 100.0);
    separation_m_ = options.separation;
    const std::array<std::array<double, 4>, 4> unit = {
        {{1.0, 0.0, 0.0, 0.0}, {0.0, 1.0, 0.0, 0.0}, {0.0, 0.0, 1.0, 0.0}, {0.0, 0.0, 0.0, 1.0}}};
    first_face_.assign(model.ElementCount() + 1, 0);
    for (std::size_t s = 0; s < geometry_.strips().size(); ++s) {
      const FrameFaces::Strip& strip = geometry_.strips()[s];
      Face face;
      face.index = static_cast<int>(s);
      face.element = strip.element;
      face.gap_m = strip.gap_m;
      face.width_m = strip.width_m;
      Eigen::Matrix<double, 12, 4> global;
      for (int k = 0; k < 4; ++k) {
        face.local.col(k) = geometry_.StripLocal(strip, unit[k]);
        global.col(k) = geometry_.StripWeights(strip, unit[k]);
      }
      SetWeights(face, model.ElementDofs(strip.element), global);
      faces_.push_back(face);
      for (const double p : rule_.points) strip_phi_.push_back(StripPhi(Along(strip, p)));
      for (const double p : {0.0, 0.5, 1.0}) strip_phi_.push_back(StripPhi(Along(strip, p)));
      ++first_face_[strip.element + 1];
    }
    for (int e = 0; e < model.ElementCount(); ++e) first_face_[e + 1] += first_face_[e];
    for (std::size_t p = 0; p < geometry_.plates().size(); ++p) {
      const FrameFaces::Plate& plate = geometry_.plates()[p];
      Face face;
      face.plate = true;
      face.index = static_cast<int>(p);
      face.gap_m = plate.gap_m;
      face.width_m = plate.width_m;
      // The coefficients are the carrier's u_y, theta_x, theta_z themselves.
      Eigen::Matrix<double, 12, 4> global = Eigen::Matrix<double, 12, 4>::Zero();
      global(0, 0) = global(1, 1) = global(2, 2) = 1.0;
      SetWeights(face, plate.dofs, global);
      faces_.push_back(face);
    }
  }

  const std::vector<Face>& faces() const { return faces_; }
  /// metres per internal length unit
  double length_m() const { return length_m_; }
  /// The substrate plane's y [m].
  double substrate_m() const { return geometry_.substrate_m(); }
  /// Whether a gap the quadrature passed [m] is the contact's separation holding it: a pressure
  /// is constant there, its slope zero.
  bool Held(double gap_m) const { return separation_m_ > 0.0 && gap_m <= separation_m_; }

  /// Adds r(d) to `force` and its tangent to `tangent`, law(face, gap [m], area [m^2], v_y)
  /// giving the point's force along its motion toward +y and that force's derivative per
  /// internal length unit of the motion, both in internal force units and both proportional to
  /// the area; v_y is the point's velocity toward +y for the velocity `v` (internal units; 0
  /// without one). A velocity reaches the strips alone: throws std::invalid_argument for one
  /// where the plates are integrated (a plate's film has its own law, FrameSqueezeFilm). False
  /// where a gap closes or is not finite. The tangent is left out where !tangent.band_wanted().
  template <typename Law>
  bool Integrate(const Eigen::VectorXd& d, const Eigen::VectorXd* v, Law&& law,
                 Eigen::VectorXd& force, ForceTangent& tangent) const {
    if (v && plates_) {
      throw std::invalid_argument("FrameGapIntegral: a velocity needs plates = false");
    }
    const bool band = tangent.band_wanted();
    for (const Face& face : faces_) {
      if (face.plate && !plates_) continue;
      Eigen::Vector4d f = Eigen::Vector4d::Zero();
      Eigen::Matrix4d t = Eigen::Matrix4d::Zero();
      if (!Gather(face, d, v, law, band, f, t)) return false;
      for (int i = 0; i < face.count; ++i) force[face.dof[i]] += face.weights.row(i).dot(f);
      if (!band) continue;
      for (int a = 0; a < 4; ++a) {
        for (int b = 0; b < a; ++b) t(a, b) = t(b, a);
      }
      for (int i = 0; i < face.count; ++i) {
        const Eigen::Vector4d ti = t * face.weights.row(i).transpose();
        for (int j = i; j < face.count; ++j) {
          tangent.band().Add(face.dof[i], face.dof[j], face.weights.row(j).dot(ti));
        }
      }
    }
    return true;
  }

  /// Element e's share of the force law(face, gap [m], area [m^2]) gives along each point's
  /// motion (proportional to the area), in its local degrees of freedom.
  template <typename Law>
  FrameModel::ElementVector LocalForce(const Eigen::VectorXd& d, int e, Law&& law) const {
    FrameModel::ElementVector out = FrameModel::ElementVector::Zero();
    const auto as_law = WithoutSlope(law);
    for (int k = first_face_[e]; k < first_face_[e + 1]; ++k) {
      Eigen::Vector4d f = Eigen::Vector4d::Zero();
      Eigen::Matrix4d t;
      Gather(faces_[k], d, nullptr, as_law, false, f, t);
      out += faces_[k].local * f;
    }
    return out;
  }

  /// The integral over the faces of value(face, gap [m], area [m^2]), a density times the area;
  /// NaN where a gap closes.
  template <typename Value>
  double Sum(const Eigen::VectorXd& d, Value&& value) const {
    double sum = 0.0;
    const auto as_law = WithoutSlope(value);
    for (const Face& face : faces_) {
      if (face.plate && !plates_) continue;
      Eigen::Vector4d f = Eigen::Vector4d::Zero();
      Eigen::Matrix4d t;
      if (!Gather(face, d, nullptr, as_law, false, f, t)) {
        return std::numeric_limits<double>::quiet_NaN();
      }
      // The combination of the coefficients that is 1 all over the face: on a strip the Hermite
      // shapes of the end values sum to 1, on a plate phi's first entry is 1.
      sum += face.plate ? f[0] : f[0] + f[2];
    }
    return sum;
  }

 private:
  // Keeps the rows of the element's (or carrier's) degrees of freedom that move the face, merged
  // by dof (an element whose ends share a body) and without the rotation's round-off (below
  // 1e-12 of the largest weight), as DofWeights does.
  static void SetWeights(Face& face, const std::array<int, 12>& dofs,
                         const Eigen::Matrix<double, 12, 4>& global) {
    const double largest = global.cwiseAbs().maxCoeff();
    face.count = 0;
    for (int a = 0; a < 12; ++a) {
      if (dofs[a] < 0) continue;
      Eigen::Matrix<double, 1, 4> row = global.row(a);
      for (int k = 0; k < 4; ++k) {
        if (std::abs(row[k]) <= 1e-12 * largest) row[k] = 0.0;
      }
      if (row.isZero()) continue;
      int* end = face.dof.data() + face.count;
      int* at = std::find(face.dof.data(), end, dofs[a]);
      if (at == end) {
        face.dof[face.count] = dofs[a];
        face.weights.row(face.count++) = row;
      } else {
        face.weights.row(at - face.dof.data()) += row;
      }
    }
  }

  // The face's coefficients B^T x for the vector x.
  static Eigen::Vector4d Coefficients(const Face& face, const Eigen::VectorXd& x) {
    Eigen::Vector4d c = Eigen::Vector4d::Zero();
    for (int i = 0; i < face.count; ++i) c += x[face.dof[i]] * face.weights.row(i).transpose();
    return c;
  }

  // The gap [m] for the coefficients c (internal units) at phi, at least the separation (NaN
  // stays NaN).
  double Gap(const Face& face, const Eigen::Vector4d& c, const Eigen::Vector4d& phi) const {
    return AtLeastSeparation(face.gap_m + c.dot(phi) * length_m_);
  }
  double AtLeastSeparation(double gap) const { return gap < separation_m_ ? separation_m_ : gap; }
  // Whether a gap is open and finite: a closed or non-finite one ends the quadrature.
  static bool Open(double gap) { return gap > 0.0 && std::isfinite(gap); }
  // The element's coordinate at the fraction p of the strip.
  static double Along(const FrameFaces::Strip& strip, double p) {
    return strip.lo + p * (strip.hi - strip.lo);
  }
  static Eigen::Vector4d StripPhi(double xi) {
    const std::array<double, 4> h = HermiteShapes(xi);
    return {h[0], h[1], h[2], h[3]};
  }
  Eigen::Vector4d PlatePhi(double x, double z) const {
    return {1.0, -z * per_length_m_, x * per_length_m_, 0.0};
  }

  // A density value(face, gap, area) as a law (Integrate's) of no slope.
  template <typename Value>
  static auto WithoutSlope(Value& value) {
    return [&value](const Face& face, double gap, double area, double /*vy*/) {
      return std::pair{value(face, gap, area), 0.0};
    };
  }

  // The face's integrals for the law (Integrate's) at the state d and velocity v (or none):
  // f += integral of value phi and, where `band`, t's upper triangle += integral of
  // slope phi phi^T. False where a gap closes or is not finite.
  template <typename Law>
  bool Gather(const Face& face, const Eigen::VectorXd& d, const Eigen::VectorXd* v, Law& law,
              bool band, Eigen::Vector4d& f, Eigen::Matrix4d& t) const {
    const Eigen::Vector4d c = Coefficients(face, d);
    const Eigen::Vector4d cv = v ? Coefficients(face, *v) : Eigen::Vector4d::Zero();
    const auto at = [&](const Eigen::Vector4d& phi, double gap, double area) {
      const auto [value, slope] = law(face, gap, area, cv.dot(phi));
      f += value * phi;
      if (band) AddOuter(t, slope, phi);
    };
    if (!face.plate) return GatherStrip(face, c, cv, at, law, band, f, t);
    const auto at_level = [&](double gap, double area) { return law(face, gap, area, 0.0); };
    return GatherPlate(face, c, at, at_level, band, f, t);
  }

  // t's upper triangle += w phi phi^T.
  static void AddOuter(Eigen::Matrix4d& t, double w, const Eigen::Vector4d& phi) {
    for (int a = 0; a < 4; ++a) {
      const double wa = w * phi[a];
      for (int b = a; b < 4; ++b) t(a, b) += wa * phi[b];
    }
  }

  // The cubic Lagrange polynomials of the nodes 0, 1/3, 2/3 and 1 at tau.
  static std::array<double, 4> CubicLagrange(double tau) {
    const double x = 3.0 * tau, x1 = x - 1.0, x2 = x - 2.0, x3 = x - 3.0;
    return {-x1 * x2 * x3 / 6.0, 0.5 * x * x2 * x3, -0.5 * x * x1 * x3, x * x1 * x2 / 6.0};
  }

  // A strip's integrals (Gather's): at(phi, gap, area) at each point of the rule over all of it
  // where its gap is within the ratio, law(face, gap, area, v_y) at each point of its halving
  // where it is not; cv: the velocity's coefficients.
  template <typename AtPoint, typename Law>
  bool GatherStrip(const Face& face, const Eigen::Vector4d& c, const Eigen::Vector4d& cv,
                   AtPoint& at, Law& law, bool band, Eigen::Vector4d& f, Eigen::Matrix4d& t) const {
    const FrameFaces::Strip& strip = geometry_.strips()[face.index];
    const double area_per_xi = strip.length_m * strip.width_m;
    // The whole strip first, on the shapes kept for it: most strips need no halving.
    const std::size_t n = rule_.points.size();
    const Eigen::Vector4d* whole = &strip_phi_[face.index * (n + 3)];
    const double g_lo = Gap(face, c, whole[n]), g_hi = Gap(face, c, whole[n + 2]);
    const double g_mid = Gap(face, c, whole[n + 1]);
    if (!(Open(g_lo) && Open(g_mid) && Open(g_hi))) return false;
    const double low = std::min({g_lo, g_mid, g_hi}), high = std::max({g_lo, g_mid, g_hi});
    if (high <= ratio_ * low) {
      for (std::size_t k = 0; k < n; ++k) {
        at(whole[k], Gap(face, c, whole[k]),
           rule_.weights[k] * (strip.hi - strip.lo) * area_per_xi);
      }
      return true;
    }
    // Halved from its two halves, whose gaps are known. phi = H^T (1, xi, xi^2, xi^3), so the
    // gap and v_y are cubics of xi, and the points need only the pressure's integrals against
    // the powers of xi: value up to xi^3 (f = H^T those), slope up to xi^6 (t = H^T M H, M the
    // Hankel matrix of those).
    Eigen::Vector4d gap = Eigen::Vector4d::Zero(), vy = Eigen::Vector4d::Zero();
    for (int a = 0; a < 4; ++a) {
      for (int j = 0; j < 4; ++j) {
        gap[j] += kHermitePowers[a][j] * c[a] * length_m_;
        vy[j] += kHermitePowers[a][j] * cv[a];
      }
    }
    gap[0] += face.gap_m;
    const auto cubic = [](const Eigen::Vector4d& a, double xi) {
      return a[0] + xi * (a[1] + xi * (a[2] + xi * a[3]));
    };
    const auto gap_at = [&](double xi) { return AtLeastSeparation(cubic(gap, xi)); };
    std::array<double, 4> value{};
    std::array<double, 7> slope{};
    const auto point = [&](double xi, double weight) {
      const auto [p, dp] = law(face, gap_at(xi), weight * area_per_xi, cubic(vy, xi));
      double power = 1.0;
      for (int j = 0; j < 7; ++j) {
        if (j < 4) value[j] += p * power;
        if (band) slope[j] += dp * power;
        power *= xi;
      }
    };
    const double m = 0.5 * (strip.lo + strip.hi);
    if (!(Halving(strip.lo, m, g_lo, g_mid, gap_at, point) &&
          Halving(m, strip.hi, g_mid, g_hi, gap_at, point))) {
      return false;
    }
    for (int a = 0; a < 4; ++a) {
      for (int j = 0; j < 4; ++j) f[a] += kHermitePowers[a][j] * value[j];
    }
    if (!band) return true;
    for (int a = 0; a < 4; ++a) {
      for (int b = a; b < 4; ++b) {
        for (int i = 0; i < 4; ++i) {
          for (int j = 0; j < 4; ++j) {
            t(a, b) += kHermitePowers[a][i] * kHermitePowers[b][j] * slope[i + j];
          }
        }
      }
    }
    return true;
  }

  // A plate's integrals (Gather's): at(phi, gap, area) at each point of the tensor rule where its
  // gap is within the ratio, at_level(gap, area) -> (value, slope) along its level lines where
  // it is not.
  template <typename AtPoint, typename AtLevel>
  bool GatherPlate(const Face& face, const Eigen::Vector4d& c, AtPoint& at, AtLevel& at_level,
                   bool band, Eigen::Vector4d& f, Eigen::Matrix4d& t) const {
    const FrameFaces::Plate& plate = geometry_.plates()[face.index];
    // The gap is linear, u = u_0 + s_x x + s_z z before the separation holds it, so its extremes
    // are at the corners.
    const double u0 = face.gap_m + c[0] * length_m_, slope_x = c[2], slope_z = -c[1];
    std::array<double, 4> corners{};
    double low = std::numeric_limits<double>::infinity(), high = 0.0;
    for (int k = 0; k < 4; ++k) {
      corners[k] = u0 + slope_x * plate.x[k & 1] + slope_z * plate.z[k >> 1];
      const double gap = AtLeastSeparation(corners[k]);
      if (!Open(gap)) return false;
      low = std::min(low, gap);
      high = std::max(high, gap);
    }
    if (high <= ratio_ * low) {  // the whole plate on the tensor rule: most plates
      const double area = (plate.x[1] - plate.x[0]) * (plate.z[1] - plate.z[0]);
      for (std::size_t i = 0; i < rule_.points.size(); ++i) {
        for (std::size_t j = 0; j < rule_.points.size(); ++j) {
          const Eigen::Vector4d phi =
              PlatePhi(plate.x[0] + rule_.points[i] * (plate.x[1] - plate.x[0]),
                       plate.z[0] + rule_.points[j] * (plate.z[1] - plate.z[0]));
          at(phi, Gap(face, c, phi), rule_.weights[i] * rule_.weights[j] * area);
        }
      }
      return true;
    }
    // Along the gap's level lines: the pressure is constant on each, so the plate is one integral
    // over u, halved as a strip is, of the pressure times the integrals along the level line of
    // u's chord of the rectangle, of phi (S(u)) and of phi phi^T (T(u)). Cells halved in x and z
    // instead refine around the whole line where the plate nears the substrate: measured, a
    // tilted shuttle 20 nm off it took ~120 cells of 16 points an evaluation. u is the level's
    // coordinate along the side whose gap changes most (p, its slope k_p), the chord's along the
    // other (q, k_q): p = (u - u_0 - k_q q) / k_p.
    const bool along_x = std::abs(slope_x) * (plate.x[1] - plate.x[0]) >=
                         std::abs(slope_z) * (plate.z[1] - plate.z[0]);
    const double k_p = along_x ? slope_x : slope_z, k_q = along_x ? slope_z : slope_x;
    const double per_kp = 1.0 / k_p, per_kq = k_q != 0.0 ? 1.0 / k_q : 0.0;
    const std::array<double, 2>& p_side = along_x ? plate.x : plate.z;
    const std::array<double, 2>& q_side = along_x ? plate.z : plate.x;
    // S(u) and T(u)'s upper triangle: phi is linear along a chord, and the two-point Gauss rule
    // on it exact.
    const auto chord = [&](double u, Eigen::Vector4d& s, Eigen::Matrix4d& m) {
      s.setZero();
      m.setZero();
      double q0 = q_side[0], q1 = q_side[1];
      if (k_q != 0.0) {
        const double qa = (u - u0 - k_p * p_side[0]) * per_kq;
        const double qb = (u - u0 - k_p * p_side[1]) * per_kq;
        q0 = std::max(q0, std::min(qa, qb));
        q1 = std::min(q1, std::max(qa, qb));
      }
      if (!(q1 > q0)) return;
      const double half = 0.5 * (q1 - q0);
      for (const double at_q : {0.5 - kChordPoint, 0.5 + kChordPoint}) {
        const double q = q0 + at_q * (q1 - q0), p = (u - u0 - k_q * q) * per_kp;
        const Eigen::Vector4d phi = along_x ? PlatePhi(p, q) : PlatePhi(q, p);
        s += half * phi;
        AddOuter(m, half, phi);
      }
    };
    // Breaks where the chord's ends turn a corner and where the separation starts to hold the
    // gap. Between two, each end of the chord stays on one side: S is a quadratic of u and T a
    // cubic, each the cubic through its values at four nodes of the piece. The pressure is then
    // integrated against each node's Lagrange polynomial, and S and T are needed at the nodes
    // alone, not at every point.
    std::array<double, 5> breaks{};
    std::copy(corners.begin(), corners.end(), breaks.begin());
    std::sort(breaks.begin(), breaks.begin() + 4);
    int count = 4;
    if (separation_m_ > breaks[0] && separation_m_ < breaks[3]) breaks[count++] = separation_m_;
    std::sort(breaks.begin(), breaks.begin() + count);
    const double per_u = 1.0 / std::abs(k_p);  // dA = du dq / |k_p|
    const auto gap_at = [&](double u) { return AtLeastSeparation(u); };
    Eigen::Vector4d s;
    Eigen::Matrix4d m;
    for (int piece = 0; piece + 1 < count; ++piece) {
      const double a = breaks[piece], b = breaks[piece + 1];
      if (!(b > a)) continue;
      std::array<double, 4> value{}, slope{};  // against each node's Lagrange polynomial
      const double per_width = 1.0 / (b - a);
      const auto point = [&](double u, double weight) {
        const auto [p, dp] = at_level(gap_at(u), weight * per_u);
        const std::array<double, 4> lagrange = CubicLagrange((u - a) * per_width);
        for (int i = 0; i < 4; ++i) {
          value[i] += p * lagrange[i];
          if (band) slope[i] += dp * lagrange[i];
        }
      };
      if (!Halving(a, b, gap_at(a), gap_at(b), gap_at, point)) return false;
      for (int i = 0; i < 4; ++i) {
        chord(i == 3 ? b : a + (b - a) * i / 3.0, s, m);
        f += value[i] * s;
        if (band) t += slope[i] * m;
      }
    }
    return true;
  }

  // The Gauss rule over [a, b], whose ends' gaps are ga and gb: point(x, weight) at each point of
  // each piece, [a, b] halved depth-first until the largest of a piece's gaps at its ends and
  // midpoint (gap_at) is at most ratio_ times its smallest. A fixed stack: 2^-40 of the range is
  // far below any ratio. False where a midpoint's gap is closed.
  template <typename GapAt, typename AtPoint>
  bool Halving(double a, double b, double ga, double gb, const GapAt& gap_at,
               const AtPoint& point) const {
    struct Interval {
      double a, b, ga, gb;
    };
    std::array<Interval, 48> stack;
    int top = 0;
    stack[top++] = {a, b, ga, gb};
    while (top > 0) {
      const Interval i = stack[--top];
      const double mid = 0.5 * (i.a + i.b), gm = gap_at(mid);
      if (!Open(gm)) return false;
      const double lo = std::min({i.ga, gm, i.gb}), hi = std::max({i.ga, gm, i.gb});
      if (hi > ratio_ * lo && top + 2 <= static_cast<int>(stack.size())) {
        stack[top++] = {mid, i.b, gm, i.gb};
        stack[top++] = {i.a, mid, i.ga, gm};
        continue;
      }
      for (std::size_t k = 0; k < rule_.points.size(); ++k) {
        point(i.a + rule_.points[k] * (i.b - i.a), rule_.weights[k] * (i.b - i.a));
      }
    }
    return true;
  }

  // The Hermite cubics' coefficients of the powers 1, xi, xi^2, xi^3 (HermiteShapes), a row each.
  static constexpr std::array<std::array<double, 4>, 4> kHermitePowers = {
      {{1.0, 0.0, -3.0, 2.0}, {0.0, 1.0, -2.0, 1.0}, {0.0, 0.0, 3.0, -2.0}, {0.0, 0.0, -1.0, 1.0}}};
  // The two-point Gauss rule's points on [0, 1] are 1/2 -+ this.
  static constexpr double kChordPoint = 0.28867513459481288225;  // 1 / (2 sqrt 3)

  FrameFaces geometry_;
  double length_m_;
  double per_length_m_;  ///< internal length units per metre
  double ratio_;
  bool plates_;
  GaussLegendre rule_;
  double separation_m_ = 0.0;
  std::vector<Face> faces_;
  std::vector<int> first_face_;  ///< element e's faces: [first_face_[e], first_face_[e + 1])
  /// Each strip's shapes at the Gauss points over all of it, then at its ends and midpoint.
  std::vector<Eigen::Vector4d> strip_phi_;
};

}  // namespace cosmems
