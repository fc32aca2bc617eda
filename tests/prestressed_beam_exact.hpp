#pragma once

// The exact free vibration of a prismatic beam under a constant axial force,
// EI w'''' - N w'' - rho A w^2 w = 0: the characteristic determinant of its boundary conditions,
// scanned and bisected to round-off. An oracle independent of any element.

#include <Eigen/Dense>
#include <cmath>

namespace cosmems::test {

// Columns: cosh(a x), sinh(a x), cos(b x), sin(b x); row k holds their k-th derivative at x.
inline Eigen::Matrix4d PrestressedBasis(double a, double b, double x) {
  const double ch = std::cosh(a * x), sh = std::sinh(a * x), c = std::cos(b * x),
               s = std::sin(b * x);
  Eigen::Matrix4d m;
  m << ch, sh, c, s,                                   //
      a * sh, a * ch, -b * s, b * c,                   //
      a * a * ch, a * a * sh, -b * b * c, -b * b * s,  //
      a * a * a * sh, a * a * a * ch, b * b * b * s, -b * b * b * c;
  return m;
}

// Nondimensional (L = EI = rho A = 1): the lowest lambda = w^2 > 0 at which the boundary
// conditions admit a solution, for a tension tau (negative: compression).
inline double ExactPrestressedLambda(bool bridge, double tau, int mode) {
  auto det = [&](double lambda) {
    const double root = std::sqrt(tau * tau + 4 * lambda);
    const double a = std::sqrt(0.5 * (tau + root));
    const double b = std::sqrt(0.5 * (-tau + root));
    const Eigen::Matrix4d at0 = PrestressedBasis(a, b, 0.0), at1 = PrestressedBasis(a, b, 1.0);
    Eigen::Matrix4d bc;
    bc.row(0) = at0.row(0);  // clamped at x = 0
    bc.row(1) = at0.row(1);
    if (!bridge) {
      bc.row(2) = at1.row(2);                     // no moment
      bc.row(3) = at1.row(3) - tau * at1.row(1);  // no transverse force
    } else {
      bc.row(2) = at1.row(0);
      bc.row(3) = at1.row(1);
    }
    return bc.determinant();
  };
  // Scan on a geometric grid for the mode-th sign change, then bisect to round-off.
  double lo = 1e-3, f_lo = det(lo);
  int found = 0;
  for (double hi = lo * 1.01; hi < 1e8; hi *= 1.01) {
    const double f_hi = det(hi);
    if ((f_lo < 0) != (f_hi < 0) && ++found == mode) {
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((det(mid) < 0) == (f_lo < 0) ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    }
    lo = hi;
    f_lo = f_hi;
  }
  return -1.0;
}

}  // namespace cosmems::test
