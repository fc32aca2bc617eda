#pragma once

#include <algorithm>
#include <type_traits>

namespace cosmems::internal {

// Kernels on LAPACK-style lower band storage (column j holds A(j + k, j) at a[j * stride + k],
// k = 0 ... W), with the half-bandwidth W a compile-time constant so that the inner loops
// unroll. Beams have W = 5 (planar) and W = 11 (spatial); DispatchBandwidth() picks the
// instantiation. Pointers are __restrict: outputs never alias the matrix or the input.

/// y += A x for a symmetric band matrix, as independent row dot-products (no row waits on
/// another, so they overlap fully).
template <int W>
void SymmetricBandMultiplyAdd(const double* __restrict a, int stride, int n,
                              const double* __restrict x, double* __restrict y) {
  for (int i = 0; i < n; ++i) {
    const double* column = a + static_cast<long>(i) * stride;
    double sum = column[0] * x[i];
    if (i >= W && i + W < n) {
      for (int k = 1; k <= W; ++k) {
        sum += column[k] * x[i + k] + a[static_cast<long>(i - k) * stride + k] * x[i - k];
      }
    } else {
      for (int k = 1; k <= W; ++k) {
        if (i + k < n) sum += column[k] * x[i + k];
        if (i - k >= 0) sum += a[static_cast<long>(i - k) * stride + k] * x[i - k];
      }
    }
    y[i] += sum;
  }
}

/// Solves L L^T x = b in place from the factor pre-scaled by its pivots: `forward` holds
/// L(i, i-k) / L(i, i) at [(i-k) stride + k], `backward` holds L(j+k, j) / L(j, j) at
/// [j stride + k], `inverse` 1 / L(i, i).
///
/// Both sweeps are latency-bound: row i needs row i - 1. With the pivots folded in and the
/// older terms summed first, a single multiply-add per row lies on the critical path.
template <int W>
void BandCholeskySolve(const double* __restrict forward, const double* __restrict backward,
                       int stride, const double* __restrict inverse, int n, double* __restrict b) {
  // The two newest values stay in registers: a value stored one or two rows ago would come
  // back through store-to-load forwarding, which adds its latency to the critical path.
  double newest = 0.0, second = 0.0;
  for (int i = 0; i < n; ++i) {
    const int reach = std::min(W, i);
    double s = b[i] * inverse[i];
    for (int k = reach; k >= 3; --k) s -= forward[static_cast<long>(i - k) * stride + k] * b[i - k];
    if (reach >= 2) s -= forward[static_cast<long>(i - 2) * stride + 2] * second;
    if (reach >= 1) s -= forward[static_cast<long>(i - 1) * stride + 1] * newest;
    second = newest;
    b[i] = newest = s;
  }
  for (int j = n - 1; j >= 0; --j) {
    const double* column = backward + static_cast<long>(j) * stride;
    const int reach = std::min(W, n - 1 - j);
    double s = b[j] * inverse[j];
    for (int k = reach; k >= 3; --k) s -= column[k] * b[j + k];
    if (reach >= 2) s -= column[2] * second;
    if (reach >= 1) s -= column[1] * newest;
    second = newest;
    b[j] = newest = s;
  }
}

/// (A x)_i for a symmetric band matrix: one row's dot product.
template <int W>
inline double SymmetricBandRow(const double* __restrict a, int stride, int n, const double* __restrict x,
                               int i) {
  const double* column = a + static_cast<long>(i) * stride;
  double sum = column[0] * x[i];
  for (int k = 1; k <= W; ++k) {
    if (i + k < n) sum += column[k] * x[i + k];
    if (i - k >= 0) sum += a[static_cast<long>(i - k) * stride + k] * x[i - k];
  }
  return sum;
}

/// out = (L L^T)^-1 (c - A1 x1 - A2 x2), the right-hand side formed row by row inside the
/// forward sweep: those products do not depend on the sweep, so they fill the arithmetic units
/// the latency-bound sweep leaves idle. A1 is skipped when `a1` is null. Factor storage as in
/// BandCholeskySolve; A1 and A2 share its band.
template <int W>
void BandCholeskySolveResidual(const double* __restrict forward, const double* __restrict backward,
                               int stride, const double* __restrict inverse, int n,
                               const double* __restrict c, const double* __restrict a1,
                               const double* __restrict x1, const double* __restrict a2,
                               const double* __restrict x2, int a_stride, double* __restrict out) {
  double newest = 0.0, second = 0.0;
  for (int i = 0; i < n; ++i) {
    double rhs = c[i] - SymmetricBandRow<W>(a2, a_stride, n, x2, i);
    if (a1 != nullptr) rhs -= SymmetricBandRow<W>(a1, a_stride, n, x1, i);
    const int reach = std::min(W, i);
    double s = rhs * inverse[i];
    for (int k = reach; k >= 3; --k) s -= forward[static_cast<long>(i - k) * stride + k] * out[i - k];
    if (reach >= 2) s -= forward[static_cast<long>(i - 2) * stride + 2] * second;
    if (reach >= 1) s -= forward[static_cast<long>(i - 1) * stride + 1] * newest;
    second = newest;
    out[i] = newest = s;
  }
  for (int j = n - 1; j >= 0; --j) {
    const double* column = backward + static_cast<long>(j) * stride;
    const int reach = std::min(W, n - 1 - j);
    double s = out[j] * inverse[j];
    for (int k = reach; k >= 3; --k) s -= column[k] * out[j + k];
    if (reach >= 2) s -= column[2] * second;
    if (reach >= 1) s -= column[1] * newest;
    second = newest;
    out[j] = newest = s;
  }
}

/// Calls f(std::integral_constant<int, W>{}) for the bandwidths beams produce and returns true,
/// or returns false so that the caller takes its general path.
template <typename F>
bool DispatchBandwidth(int bandwidth, F&& f) {
  switch (bandwidth) {
    case 0: f(std::integral_constant<int, 0>{}); return true;
    case 1: f(std::integral_constant<int, 1>{}); return true;
    case 2: f(std::integral_constant<int, 2>{}); return true;
    case 3: f(std::integral_constant<int, 3>{}); return true;
    case 4: f(std::integral_constant<int, 4>{}); return true;
    case 5: f(std::integral_constant<int, 5>{}); return true;
    case 8: f(std::integral_constant<int, 8>{}); return true;
    case 11: f(std::integral_constant<int, 11>{}); return true;
    default: return false;
  }
}

}  // namespace cosmems::internal
