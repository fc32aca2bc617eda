// The power-series element terms against two independent evaluations:
//  1. the recursion n_r'''' = n_(r-1) (n_r'' = -n_(r-1) for a bar) solved numerically by
//     Cauchy's repeated-integration formula and Gauss-Legendre quadrature, then the element
//     integrals taken by quadrature: no polynomial algebra shared with the library;
//  2. the exact (transcendental) dynamic stiffness of the element, whose Taylor coefficients in
//     w^2 the mass terms must be.
#include "cosmems/beam/power_series_basis.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>
#include <functional>
#include <vector>

namespace cosmems {
namespace {

// 24-point Gauss-Legendre on [0, 1] (exact to degree 47), built by Newton on P_24.
struct Gauss {
  std::vector<double> x, w;
  explicit Gauss(int n) {
    for (int i = 1; i <= n; ++i) {
      double t = std::cos(3.14159265358979323846 * (i - 0.25) / (n + 0.5));
      double dp = 0.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = t;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (t * p1 - p0) / (t * t - 1);
        t -= p1 / dp;
      }
      x.push_back(0.5 * (1 + t));
      w.push_back(1.0 / ((1 - t * t) * dp * dp));
    }
  }
  double Integrate(double a, double b, const std::function<double(double)>& f) const {
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) sum += w[i] * f(a + (b - a) * x[i]);
    return (b - a) * sum;
  }
};

const Gauss& Rule() {
  static const Gauss rule(24);
  return rule;
}

using Fn = std::function<double(double)>;

// Static shape functions written out by hand.
std::vector<Fn> StaticShapes(FieldKind kind) {
  if (kind == FieldKind::kBar) return {[](double s) { return 1 - s; }, [](double s) { return s; }};
  return {[](double s) { return 1 - 3 * s * s + 2 * s * s * s; },
          [](double s) { return s - 2 * s * s + s * s * s; },
          [](double s) { return 3 * s * s - 2 * s * s * s; },
          [](double s) { return -s * s + s * s * s; }};
}

// The next term of the recursion with homogeneous nodal values: by Cauchy's formula the m-fold
// integral from 0 is int_0^xi (xi - s)^(m-1) / (m-1)! f(s) ds; the homogeneous part fixes xi = 1.
Fn NextShape(FieldKind kind, Fn f) {
  const Gauss& g = Rule();
  if (kind == FieldKind::kBar) {
    auto i2 = [f, &g](double xi) {
      return -g.Integrate(0, xi, [&](double s) { return (xi - s) * f(s); });
    };
    const double at1 = i2(1.0);
    return [i2, at1](double xi) { return i2(xi) - at1 * xi; };
  }
  auto i4 = [f, &g](double xi) {
    return g.Integrate(0, xi, [&](double s) { return std::pow(xi - s, 3) / 6 * f(s); });
  };
  auto d1 = [f, &g](double xi) {
    return g.Integrate(0, xi, [&](double s) { return std::pow(xi - s, 2) / 2 * f(s); });
  };
  const double v = i4(1.0), dv = d1(1.0);
  const double c2 = -3 * v + dv, c3 = 2 * v - dv;
  return [i4, c2, c3](double xi) { return i4(xi) + c2 * xi * xi + c3 * xi * xi * xi; };
}

class PowerSeriesBasisTest : public ::testing::TestWithParam<std::tuple<FieldKind, int>> {};

// Quadrature of the numerically recursed functions reproduces the exact polynomial integrals to
// round-off; 1e-10 relative to the largest entry of each matrix leaves room for the nested
// quadrature's accumulation (values down to 1e-12 of the entries of M_0 at order 3).
TEST_P(PowerSeriesBasisTest, MassTermsMatchQuadratureOfTheRecursion) {
  const auto [kind, order] = GetParam();
  const PowerSeriesBasis basis(kind, order);
  std::vector<Fn> shapes = StaticShapes(kind);
  for (int r = 1; r <= order; ++r) {
    for (Fn& f : shapes) f = NextShape(kind, f);
  }
  const std::vector<Fn> base = StaticShapes(kind);
  const Eigen::MatrixXd& m = basis.Mass(order);
  for (int a = 0; a < basis.NodalValues(); ++a) {
    for (int b = 0; b < basis.NodalValues(); ++b) {
      const double expected =
          0.5 * (Rule().Integrate(0, 1, [&](double s) { return shapes[a](s) * base[b](s); }) +
                 Rule().Integrate(0, 1, [&](double s) { return shapes[b](s) * base[a](s); }));
      EXPECT_NEAR(m(a, b), expected, 1e-10 * m.cwiseAbs().maxCoeff())
          << "order " << order << " entry " << a << "," << b;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Orders, PowerSeriesBasisTest,
                         ::testing::Combine(::testing::Values(FieldKind::kBar, FieldKind::kBending),
                                            ::testing::Values(0, 1, 2, 3)));

TEST(PowerSeriesBasisTest, StaticTermsAreTheClassicalMatrices) {
  const PowerSeriesBasis bending(FieldKind::kBending, 0);
  Eigen::Matrix4d k;
  k << 12, 6, -12, 6, 6, 4, -6, 2, -12, -6, 12, -6, 6, 2, -6, 4;
  Eigen::Matrix4d m;
  m << 156, 22, 54, -13, 22, 4, 13, -3, 54, 13, 156, -22, -13, -3, -22, 4;
  EXPECT_LT((bending.Stiffness() - k).norm(), 1e-13 * k.norm());
  EXPECT_LT((bending.Mass(0) - m / 420).norm(), 1e-13 * m.norm() / 420);
  const PowerSeriesBasis bar(FieldKind::kBar, 0);
  EXPECT_LT((bar.Stiffness() - (Eigen::Matrix2d() << 1, -1, -1, 1).finished()).norm(), 1e-14);
  EXPECT_LT((bar.Mass(0) - (Eigen::Matrix2d() << 2, 1, 1, 2).finished() / 6).norm(), 1e-14);
}

TEST(PowerSeriesBasisTest, ShapeFunctionsSolveTheRecursionWithHomogeneousNodalValues) {
  const PowerSeriesBasis basis(FieldKind::kBending, 3);
  for (int r = 1; r <= 3; ++r) {
    for (int a = 0; a < 4; ++a) {
      const internal::Polynomial& n = basis.Shape(r, a);
      const internal::Polynomial d = internal::Derivative(n);
      EXPECT_NEAR(internal::Evaluate(n, 0), 0, 1e-15);
      EXPECT_NEAR(internal::Evaluate(n, 1), 0, 1e-15);
      EXPECT_NEAR(internal::Evaluate(d, 0), 0, 1e-15);
      EXPECT_NEAR(internal::Evaluate(d, 1), 0, 1e-15);
      internal::Polynomial d4 = n;
      for (int i = 0; i < 4; ++i) d4 = internal::Derivative(d4);
      for (double xi : {0.1, 0.5, 0.9}) {
        EXPECT_NEAR(internal::Evaluate(d4, xi), internal::Evaluate(basis.Shape(r - 1, a), xi),
                    1e-14);
      }
    }
  }
}

// Exact dynamic stiffness of a bar (EA = rho A = l = 1): D = b / sin b [[cos b, -1], [-1, cos b]]
// with b = w. Its Taylor coefficients are the mass terms: D - D_k = -b^(2k+4) M_(k+1) +
// O(b^(2k+6)).
TEST(PowerSeriesBasisTest, BarTermsAreTheTaylorCoefficientsOfTheExactDynamicStiffness) {
  const PowerSeriesBasis basis(FieldKind::kBar, 4);
  const double w2 = 0.5;  // w^2; the series converges for w^2 < pi^2
  const double b = std::sqrt(w2);
  Eigen::Matrix2d exact;
  exact << std::cos(b), -1, -1, std::cos(b);
  exact *= b / std::sin(b);
  Eigen::Matrix2d truncated = basis.Stiffness();
  for (int k = 0; k <= 3; ++k) {
    truncated -= std::pow(w2, k + 1) * basis.Mass(k);
    const Eigen::Matrix2d coefficient = -(exact - truncated) / std::pow(w2, k + 2);
    // The next term is smaller by about w^2 / pi^2 = 5 %: allow 10 %.
    EXPECT_LT((coefficient - basis.Mass(k + 1)).norm(), 0.1 * basis.Mass(k + 1).norm())
        << "order " << k;
  }
}

// Exact bending dynamic stiffness from the energy of the exact shape functions
// Phi H^-1, Phi = [cos bx, sin bx, cosh bx, sinh bx], integrated by quadrature.
TEST(PowerSeriesBasisTest, BendingTermsAreTheTaylorCoefficientsOfTheExactDynamicStiffness) {
  const PowerSeriesBasis basis(FieldKind::kBending, 4);
  const double w2 = 20.0;  // beta^4 = w^2; the series converges for w^2 < 4.73^4 = 500.6
  const double b = std::pow(w2, 0.25);
  auto phi = [b](double s, int d) {
    Eigen::Vector4d v;
    const double c = std::cos(b * s), sn = std::sin(b * s), ch = std::cosh(b * s),
                 sh = std::sinh(b * s);
    const double p = std::pow(b, d);
    switch (d % 4) {
      case 0:
        v << c, sn, ch, sh;
        break;
      case 1:
        v << -sn, c, sh, ch;
        break;
      case 2:
        v << -c, -sn, ch, sh;
        break;
      default:
        v << sn, -c, sh, ch;
        break;
    }
    return Eigen::Vector4d(p * v);
  };
  Eigen::Matrix4d h;
  h.row(0) = phi(0, 0);
  h.row(1) = phi(0, 1);
  h.row(2) = phi(1, 0);
  h.row(3) = phi(1, 1);
  const Eigen::Matrix4d hinv = h.inverse();
  Eigen::Matrix4d exact = Eigen::Matrix4d::Zero();
  const Gauss& g = Rule();
  for (std::size_t i = 0; i < g.x.size(); ++i) {
    const Eigen::RowVector4d n = phi(g.x[i], 0).transpose() * hinv;
    const Eigen::RowVector4d n2 = phi(g.x[i], 2).transpose() * hinv;
    exact += g.w[i] * (n2.transpose() * n2 - w2 * n.transpose() * n);
  }
  Eigen::Matrix4d truncated = basis.Stiffness();
  for (int k = 0; k <= 2; ++k) {
    truncated -= std::pow(w2, k + 1) * basis.Mass(k);
    const Eigen::Matrix4d coefficient = -(exact - truncated) / std::pow(w2, k + 2);
    // The next term is smaller by about w^2 / 500 = 4 %: allow 10 %.
    EXPECT_LT((coefficient - basis.Mass(k + 1)).norm(), 0.1 * basis.Mass(k + 1).norm())
        << "order " << k;
  }
}

TEST(PowerSeriesBasisTest, RejectsNegativeOrder) {
  EXPECT_THROW(PowerSeriesBasis(FieldKind::kBending, -1), std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
