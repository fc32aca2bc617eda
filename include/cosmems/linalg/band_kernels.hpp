#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace cosmems::internal {

// Kernels on LAPACK-style lower band storage (column j holds A(j + k, j) at a[j * stride + k],
// k = 0 ... W), with the half-bandwidth W a compile-time constant so that the inner loops
// unroll. Beams have W = 5 (planar) and W = 11 (spatial); DispatchBandwidth() picks the
// instantiation. Pointers are __restrict: outputs never alias the matrix or the input.

/// Two doubles in one SSE register (GCC's and Clang's vector extension): the lanes of two band
/// products taken together, which the baseline x86-64 target (no -march) otherwise computes one
/// scalar at a time.
typedef double DoublePair __attribute__((vector_size(16)));

/// y += alpha A x for a symmetric band matrix, column by column: column j gives y_j its dot
/// product with x_j ... x_(j+W) and adds A(j+k, j) x_j to the W sums still open below it, which
/// ride along in registers. Each stored entry is loaded once, where a row by row product loads
/// the lower triangle's entries across columns, strided; it is the faster of the two
/// (doc/speed.md, "Kernel choices"). With kAdd false it stores y = alpha A x instead, y needing
/// no zeroing beforehand. T is double, or DoublePair for two matrices of one pattern multiplied
/// at once (SymmetricBandPair): each lane then takes the same operations in the same order as a
/// product of its own.
template <int W, bool kAdd = true, typename T = double>
void SymmetricBandMultiplyAdd(const T* __restrict a, int stride, int n, const T* __restrict x,
                              double alpha, T* __restrict y) {
  T open[W + 1] = {};  // open[k]: what the columns before j add to row j + k
  int j = 0;
  for (; j + W < n; ++j) {  // interior columns: constant trip counts, unrolled
    const T* column = a + static_cast<long>(j) * stride;
    const T xj = x[j];
    T sum = open[0] + column[0] * xj;
    for (int k = 1; k <= W; ++k) sum += column[k] * x[j + k];
    y[j] = kAdd ? y[j] + alpha * sum : alpha * sum;
    for (int k = 1; k <= W; ++k) open[k - 1] = open[k] + column[k] * xj;
    open[W] = T{};
  }
  for (; j < n; ++j) {  // the last W columns, cut short by the matrix's end
    const T* column = a + static_cast<long>(j) * stride;
    const T xj = x[j];
    T sum = open[0] + column[0] * xj;
    for (int k = 1; k <= W && j + k < n; ++k) sum += column[k] * x[j + k];
    y[j] = kAdd ? y[j] + alpha * sum : alpha * sum;
    for (int k = 1; k <= W; ++k) open[k - 1] = j + k < n ? open[k] + column[k] * xj : open[k];
    open[W] = T{};
  }
}

/// SymmetricBandMultiplyAdd for a bandwidth known only at run time (no fixed kernel): the same
/// columns, the band's length a loop bound. T as there.
template <typename T>
void SymmetricBandMultiplyAddAnyWidth(const T* __restrict a, int stride, int n, int bandwidth,
                                      const T* __restrict x, double alpha, T* __restrict y) {
  for (int j = 0; j < n; ++j) {
    const T* column = a + static_cast<long>(j) * stride;
    T sum = column[0] * x[j];
    const int last = std::min(n - 1, j + bandwidth);
    for (int i = j + 1; i <= last; ++i) {
      y[i] += alpha * column[i - j] * x[j];
      sum += column[i - j] * x[i];
    }
    y[j] += alpha * sum;
  }
}

/// Solves L D L^T x = b in place, L unit lower with L(j+k, j) at unit[j stride + k] and 1 / D_j
/// at inverse[j], with two hooks for the work around a solve: b_i = rhs(i) is made just before
/// the forward sweep needs it, and solved(j, x_j) is called as the backward sweep finds x_j.
///
/// Row i needs row i - 1, so the sweeps cannot overlap rows, and they are bound by loads. The
/// last W solved values therefore ride along in registers (a window the compiler unrolls; a
/// value stored a row ago would also come back through store-to-load forwarding), the older
/// terms are summed first, and one multiply-add per row lies on the critical path. Work that
/// does not depend on the sweeps (a row product making b_i, an update taking x_j) runs in their
/// waits, where as a pass of its own it would cost its own time.
template <int W, typename Rhs, typename Solved>
void BandLdlSolveRows(const double* __restrict unit, int stride, const double* __restrict inverse,
                      int n, double* b, Rhs&& rhs, Solved&& solved) {
  double window[W + 1] = {};     // window[k - 1]: the value solved k rows ago
  for (int i = 0; i < n; ++i) {  // L y = b
    double s = rhs(i);
    if (i >= W) {
      for (int k = W; k >= 1; --k) s -= unit[static_cast<long>(i - k) * stride + k] * window[k - 1];
    } else {
      for (int k = i; k >= 1; --k) s -= unit[static_cast<long>(i - k) * stride + k] * window[k - 1];
    }
    for (int k = W - 1; k >= 1; --k) window[k] = window[k - 1];
    b[i] = window[0] = s;
  }
  for (int k = 0; k < W; ++k) window[k] = 0.0;
  for (int j = n - 1; j >= 0; --j) {  // L^T x = D^-1 y
    const double* column = unit + static_cast<long>(j) * stride;
    double s = b[j] * inverse[j];
    if (j + W < n) {
      for (int k = W; k >= 1; --k) s -= column[k] * window[k - 1];
    } else {
      for (int k = n - 1 - j; k >= 1; --k) s -= column[k] * window[k - 1];
    }
    for (int k = W - 1; k >= 1; --k) window[k] = window[k - 1];
    b[j] = window[0] = s;
    solved(j, s);
  }
}

/// BandLdlSolveRows with b as the right side and nothing more to do. (b is not restrict there:
/// rhs reads it.)
template <int W>
void BandLdlSolve(const double* __restrict unit, int stride, const double* __restrict inverse,
                  int n, double* __restrict b) {
  BandLdlSolveRows<W>(
      unit, stride, inverse, n, b, [b](int i) { return b[i]; }, [](int, double) {});
}

/// Factors a symmetric band matrix as A = L D L^T, L unit lower: L(j+k, j) goes to
/// unit[j stride + k] (k = 1 ... W, zero past the last row), D_j to pivot[j] and 1 / D_j to
/// inverse[j]. Returns n, or the first column j whose pivot is not above floor * A(j, j) (that
/// pivot left in pivot[j]).
///
/// Right-looking: column j, once its pivot is known, becomes L's column and takes its outer
/// product out of the W columns after it, each update a contiguous run of one column (rows
/// j + s ... j + W of column j + s), as the band is stored. Left-looking, each entry a dot
/// product over the W columns before it reads them across their storage with a stride, and took
/// 1.5 times as long (doc/speed.md, "Kernel choices"). A's column j + W enters the factor's
/// storage as column j's updates first reach it; unlike L L^T no square root is taken.
template <int W>
int BandLdlFactor(const double* __restrict a, int stride, int n, double floor,
                  double* __restrict unit, double* __restrict pivot, double* __restrict inverse) {
  const auto copy = [&](int c) {  // A's column c, its rows past the matrix's end zero
    const double* from = a + static_cast<long>(c) * stride;
    double* to = unit + static_cast<long>(c) * stride;
    if (c + W < n) {
      for (int k = 0; k <= W; ++k) to[k] = from[k];
    } else {
      for (int k = 0; k <= W; ++k) to[k] = c + k < n ? from[k] : 0.0;
    }
  };
  for (int c = 0; c < W && c < n; ++c) copy(c);
  for (int j = 0; j < n; ++j) {
    if (j + W < n) copy(j + W);
    double* column = unit + static_cast<long>(j) * stride;
    const double d = column[0];
    pivot[j] = d;
    if (!(d > floor * a[static_cast<long>(j) * stride]) || !std::isfinite(d)) return j;
    const double scale = inverse[j] = 1.0 / d;
    double t[W + 1];  // t[r] = L(j + r, j) D_j: A(j + r, j) after the columns before updated it
    for (int r = 1; r <= W; ++r) t[r] = column[r];
    for (int r = 1; r <= W; ++r) column[r] = t[r] * scale;
    column[0] = 1.0;
    // A(j + r, j + s) -= L(j + s, j) D_j L(j + r, j); target[r] is row j + r of column j + s.
    if (j + W < n) {  // interior columns: every loop bound a constant, unrolled
      for (int s = 1; s <= W; ++s) {
        double* target = unit + static_cast<long>(j + s) * stride - s;
        const double l = column[s];  // read once: the stores to target could alias it
        for (int r = s; r <= W; ++r) target[r] -= t[r] * l;
      }
    } else {
      for (int s = 1; j + s < n; ++s) {
        double* target = unit + static_cast<long>(j + s) * stride - s;
        const double l = column[s];
        for (int r = s; j + r < n; ++r) target[r] -= t[r] * l;
      }
    }
  }
  return n;
}

/// BandLdlSolve for two right-hand sides at once. The sweeps are bound by the latency of one
/// row after another, so the second system rides in the gaps of the first and costs far less
/// than a second solve (doc/speed.md, "Kernel choices").
template <int W>
void BandLdlSolve2(const double* __restrict unit, int stride, const double* __restrict inverse,
                   int n, double* __restrict b, double* __restrict c) {
  double wb[W + 1] = {}, wc[W + 1] = {};  // the values solved 1 ... W rows ago
  auto shift = [&](double sb, double sc) {
    for (int k = W - 1; k >= 1; --k) {
      wb[k] = wb[k - 1];
      wc[k] = wc[k - 1];
    }
    wb[0] = sb;
    wc[0] = sc;
  };
  for (int i = 0; i < n; ++i) {
    double sb = b[i], sc = c[i];
    const int m = i >= W ? W : i;
    if (i >= W) {
      for (int k = W; k >= 1; --k) {
        const double l = unit[static_cast<long>(i - k) * stride + k];
        sb -= l * wb[k - 1];
        sc -= l * wc[k - 1];
      }
    } else {
      for (int k = m; k >= 1; --k) {
        const double l = unit[static_cast<long>(i - k) * stride + k];
        sb -= l * wb[k - 1];
        sc -= l * wc[k - 1];
      }
    }
    shift(sb, sc);
    b[i] = sb;
    c[i] = sc;
  }
  for (int k = 0; k < W; ++k) wb[k] = wc[k] = 0.0;
  for (int j = n - 1; j >= 0; --j) {
    const double* column = unit + static_cast<long>(j) * stride;
    double sb = b[j] * inverse[j], sc = c[j] * inverse[j];
    if (j + W < n) {
      for (int k = W; k >= 1; --k) {
        sb -= column[k] * wb[k - 1];
        sc -= column[k] * wc[k - 1];
      }
    } else {
      for (int k = n - 1 - j; k >= 1; --k) {
        sb -= column[k] * wb[k - 1];
        sc -= column[k] * wc[k - 1];
      }
    }
    shift(sb, sc);
    b[j] = sb;
    c[j] = sc;
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
