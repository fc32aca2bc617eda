#pragma once

#include <Eigen/Core>

namespace cosmems::internal {

/// A polynomial on [0, 1] held by its monomial coefficients c_k of xi^k. The power-series shape
/// functions are polynomials with exact rational coefficients, so monomials lose nothing at the
/// modest degrees used here (3 + 4k for bending order k).
using Polynomial = Eigen::VectorXd;

inline double Evaluate(const Polynomial& p, double xi) {
  double value = 0.0;
  for (Eigen::Index k = p.size() - 1; k >= 0; --k) value = value * xi + p[k];
  return value;
}

inline Polynomial Derivative(const Polynomial& p) {
  if (p.size() <= 1) return Polynomial::Zero(1);
  Polynomial d(p.size() - 1);
  for (Eigen::Index k = 1; k < p.size(); ++k) d[k - 1] = static_cast<double>(k) * p[k];
  return d;
}

/// The antiderivative that vanishes at xi = 0.
inline Polynomial Antiderivative(const Polynomial& p) {
  Polynomial a = Polynomial::Zero(p.size() + 1);
  for (Eigen::Index k = 0; k < p.size(); ++k) a[k + 1] = p[k] / static_cast<double>(k + 1);
  return a;
}

/// The exact integral of p q over [0, 1].
inline double InnerProduct(const Polynomial& p, const Polynomial& q) {
  double sum = 0.0;
  for (Eigen::Index a = 0; a < p.size(); ++a) {
    for (Eigen::Index b = 0; b < q.size(); ++b) sum += p[a] * q[b] / static_cast<double>(a + b + 1);
  }
  return sum;
}

}  // namespace cosmems::internal
