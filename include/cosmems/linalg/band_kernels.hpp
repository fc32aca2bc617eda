#pragma once

#include <algorithm>
#include <type_traits>

namespace cosmems::internal {

// Kernels on LAPACK-style lower band storage (column j holds A(j + k, j) at a[j * stride + k],
// k = 0 ... W), with the half-bandwidth W a compile-time constant so that the inner loops
// unroll. Beams have W = 5 (planar) and W = 11 (spatial); DispatchBandwidth() picks the
// instantiation. Pointers are __restrict: outputs never alias the matrix or the input.

/// (A x)_i for a symmetric band matrix: one row's dot product. Interior rows, the common
/// case, run without edge tests.
template <int W>
inline double SymmetricBandRow(const double* __restrict a, int stride, int n,
                               const double* __restrict x, int i) {
  const double* column = a + static_cast<long>(i) * stride;
  double sum = column[0] * x[i];
  if (i >= W && i + W < n) {
    for (int k = 1; k <= W; ++k) {
      sum += column[k] * x[i + k] + a[static_cast<long>(i - k) * stride + k] * x[i - k];
    }
    return sum;
  }
  for (int k = 1; k <= W; ++k) {
    if (i + k < n) sum += column[k] * x[i + k];
    if (i - k >= 0) sum += a[static_cast<long>(i - k) * stride + k] * x[i - k];
  }
  return sum;
}

/// y += alpha A x for a symmetric band matrix, as independent row dot-products (no row waits
/// on another, so they overlap fully).
template <int W>
void SymmetricBandMultiplyAdd(const double* __restrict a, int stride, int n,
                              const double* __restrict x, double alpha, double* __restrict y) {
  for (int i = 0; i < n; ++i) y[i] += alpha * SymmetricBandRow<W>(a, stride, n, x, i);
}

/// Solves L L^T x = b in place from the factor pre-scaled by its pivots: `forward` holds
/// L(i, i-k) / L(i, i) at [(i-k) stride + k], `backward` L(j+k, j) / L(j, j) at
/// [j stride + k], `inverse` 1 / L(i, i).
///
/// Row i needs row i - 1, so the sweeps cannot overlap rows, and they are bound by loads. The
/// last W solved values therefore ride along in registers (a window the compiler unrolls; a
/// value stored a row ago would also come back through store-to-load forwarding), the older
/// terms are summed first, and one multiply-add per row lies on the critical path.
template <int W>
void BandCholeskySolve(const double* __restrict forward, const double* __restrict backward,
                       int stride, const double* __restrict inverse, int n, double* __restrict b) {
  double window[W + 1] = {};  // window[k - 1]: the value solved k rows ago
  for (int i = 0; i < n; ++i) {
    double s = b[i] * inverse[i];
    if (i >= W) {
      for (int k = W; k >= 1; --k)
        s -= forward[static_cast<long>(i - k) * stride + k] * window[k - 1];
    } else {
      for (int k = i; k >= 1; --k)
        s -= forward[static_cast<long>(i - k) * stride + k] * window[k - 1];
    }
    for (int k = W - 1; k >= 1; --k) window[k] = window[k - 1];
    b[i] = window[0] = s;
  }
  for (int k = 0; k < W; ++k) window[k] = 0.0;
  for (int j = n - 1; j >= 0; --j) {
    const double* column = backward + static_cast<long>(j) * stride;
    double s = b[j] * inverse[j];
    if (j + W < n) {
      for (int k = W; k >= 1; --k) s -= column[k] * window[k - 1];
    } else {
      for (int k = n - 1 - j; k >= 1; --k) s -= column[k] * window[k - 1];
    }
    for (int k = W - 1; k >= 1; --k) window[k] = window[k - 1];
    b[j] = window[0] = s;
  }
}

/// Calls f(std::integral_constant<int, W>{}) for the bandwidths beams produce and returns true,
/// or returns false so that the caller takes its general path.
template <typename F>
bool DispatchBandwidth(int bandwidth, F&& f) {
  switch (bandwidth) {
    case 0:
      f(std::integral_constant<int, 0>{});
      return true;
    case 1:
      f(std::integral_constant<int, 1>{});
      return true;
    case 2:
      f(std::integral_constant<int, 2>{});
      return true;
    case 3:
      f(std::integral_constant<int, 3>{});
      return true;
    case 4:
      f(std::integral_constant<int, 4>{});
      return true;
    case 5:
      f(std::integral_constant<int, 5>{});
      return true;
    case 8:
      f(std::integral_constant<int, 8>{});
      return true;
    case 11:
      f(std::integral_constant<int, 11>{});
      return true;
    default:
      return false;
  }
}

}  // namespace cosmems::internal
