#pragma once

#include <Eigen/Core>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/beam/polynomial.hpp"

namespace cosmems {

/// The field a power-series element interpolates.
enum class FieldKind {
  kBar,      ///< axial extension or torsion: EA u'' + rho A w^2 u = 0, 2 nodal values
  kBending,  ///< Euler-Bernoulli bending: EI w'''' - rho A w^2 w = 0, 4 nodal values
};

/// Nondimensional power-series shape functions and element matrices of one field on xi in [0, 1]
/// (Paz & Dung 1975; Przemieniecki 1966).
///
/// The dynamic shape functions are N(xi, w) = sum_r c^r w^(2r) n_r(xi) with c = rho A l^4 / EI
/// (bending) or rho A l^2 / EA (bar). n_0 are the static shape functions (Hermite cubics for the
/// nodal values w1, l theta1, w2, l theta2; linear for a bar); each further n_r solves
/// n_r'''' = n_{r-1} (bending) or n_r'' = -n_{r-1} (bar) with homogeneous nodal values. The
/// dynamic stiffness then expands as
///   D(w) = K - w^2 M_0 - w^4 M_2 - ... ,   K = int n_0'' n_0'',   M_{2j} ~ int n_j n_0,
/// where the coefficient of w^(2j+2) follows from integrating the cross terms by parts: every
/// other product cancels, leaving -(rho A) int N_j N_0 (symmetric, since int N_a N_b depends on
/// a + b only). `Stiffness()` and `Mass(j)` return the nondimensional K-hat and M-hat_j.
///
/// An axial force N adds N int N'^T N' dxi to D(w) (the geometric stiffness K_NL), which expands
/// the same way: its coefficient of w^(2j) is G-hat_j = sum_(a+b=j) int n_a' n_b' dxi, complete
/// for j <= order. `Geometric(j)` returns G-hat_j.
class PowerSeriesBasis {
 public:
  PowerSeriesBasis(FieldKind kind, int order) : kind_(kind), order_(order) {
    if (order < 0) {
      throw std::invalid_argument("model.series_order = " + std::to_string(order) +
                                  ": must be >= 0");
    }
    shapes_.push_back(StaticShapes());
    for (int r = 1; r <= order; ++r) shapes_.push_back(NextShapes(shapes_.back()));
    const int n = NodalValues();
    stiffness_.resize(n, n);
    const int derivative = kind == FieldKind::kBending ? 2 : 1;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        stiffness_(a, b) = internal::InnerProduct(Differentiate(shapes_[0][a], derivative),
                                                  Differentiate(shapes_[0][b], derivative));
      }
    }
    for (int j = 0; j <= order; ++j) {
      Eigen::MatrixXd m(n, n);
      for (int a = 0; a < n; ++a) {
        for (int b = 0; b < n; ++b) m(a, b) = internal::InnerProduct(shapes_[j][a], shapes_[0][b]);
      }
      mass_.push_back(0.5 * (m + m.transpose()));  // symmetric in exact arithmetic
    }
    for (int j = 0; j <= order; ++j) {
      Eigen::MatrixXd g = Eigen::MatrixXd::Zero(n, n);
      for (int r = 0; r <= j; ++r) {
        for (int a = 0; a < n; ++a) {
          for (int b = 0; b < n; ++b) {
            g(a, b) += internal::InnerProduct(internal::Derivative(shapes_[r][a]),
                                              internal::Derivative(shapes_[j - r][b]));
          }
        }
      }
      geometric_.push_back(0.5 * (g + g.transpose()));
    }
  }

  FieldKind kind() const { return kind_; }
  int order() const { return order_; }
  int NodalValues() const { return kind_ == FieldKind::kBending ? 4 : 2; }

  /// n_r(xi) for nodal value a.
  const internal::Polynomial& Shape(int r, int a) const { return shapes_.at(r).at(a); }
  /// K-hat = int n_0^(m)' n_0^(m) dxi, m = 2 (bending) or 1 (bar).
  const Eigen::MatrixXd& Stiffness() const { return stiffness_; }
  /// M-hat_j = int n_j n_0 dxi, the coefficient of w^(2j+2) in -D (nondimensional).
  const Eigen::MatrixXd& Mass(int j) const { return mass_.at(j); }
  /// G-hat_j = sum_(a+b=j) int n_a' n_b' dxi, the coefficient of N w^(2j) in D (nondimensional).
  const Eigen::MatrixXd& Geometric(int j) const { return geometric_.at(j); }

 private:
  using Shapes = std::vector<internal::Polynomial>;

  static internal::Polynomial Differentiate(internal::Polynomial p, int times) {
    for (int i = 0; i < times; ++i) p = internal::Derivative(p);
    return p;
  }

  Shapes StaticShapes() const {
    if (kind_ == FieldKind::kBar) {
      return {(Eigen::VectorXd(2) << 1.0, -1.0).finished(),
              (Eigen::VectorXd(2) << 0.0, 1.0).finished()};
    }
    return {(Eigen::VectorXd(4) << 1.0, 0.0, -3.0, 2.0).finished(),
            (Eigen::VectorXd(4) << 0.0, 1.0, -2.0, 1.0).finished(),
            (Eigen::VectorXd(4) << 0.0, 0.0, 3.0, -2.0).finished(),
            (Eigen::VectorXd(4) << 0.0, 0.0, -1.0, 1.0).finished()};
  }

  // Solves the next term of the recursion with homogeneous nodal values. The antiderivatives
  // vanish at xi = 0 with their derivatives, so only the xi = 1 conditions need the added
  // homogeneous solution (c2 xi^2 + c3 xi^3 for bending, c1 xi for a bar).
  Shapes NextShapes(const Shapes& previous) const {
    Shapes next;
    for (const auto& p : previous) {
      if (kind_ == FieldKind::kBar) {
        internal::Polynomial g = internal::Antiderivative(internal::Antiderivative(-p));
        g[1] -= internal::Evaluate(g, 1.0);
        next.push_back(g);
      } else {
        internal::Polynomial g = p;
        for (int i = 0; i < 4; ++i) g = internal::Antiderivative(g);
        const double value = internal::Evaluate(g, 1.0);
        const double slope = internal::Evaluate(internal::Derivative(g), 1.0);
        g[2] += -3.0 * value + slope;
        g[3] += 2.0 * value - slope;
        next.push_back(g);
      }
    }
    return next;
  }

  FieldKind kind_;
  int order_;
  std::vector<Shapes> shapes_;
  Eigen::MatrixXd stiffness_;
  std::vector<Eigen::MatrixXd> mass_;
  std::vector<Eigen::MatrixXd> geometric_;
};

}  // namespace cosmems
