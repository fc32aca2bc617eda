#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "cosmems/core/status.hpp"

namespace cosmems {

/// The Newton matrix of a chain of 6-dof nodes: symmetric, block tridiagonal with 6 x 6 blocks
/// (node i couples only to i - 1 and i + 1), plus an optional non-symmetric addition to the last
/// diagonal block, and its factorisation.
///
/// Factorisation: block LDL^T node by node, S_0 = K_00, G_i = K_(i+1),i S_i^-1,
/// S_(i+1) = K_(i+1),(i+1) - G_i K_(i+1),i^T, keeping S_i^-1 and G_i. S_i^-1 comes from its 3 x 3
/// blocks by cofactors (no square root, two divisions), and S_(i+1) from 6 x 3 pieces of that
/// elimination (see EliminateNode) in fixed-size products, which vectorise. Its pivots (those
/// of S_i's LDL^T) are checked as BandCholesky checks its own. On the rod's matrix it factors and
/// solves about three and two times faster than BandCholesky on the same matrix in band storage,
/// and faster than the block variants it replaced (doc/speed.md, "Kernel choices";
/// cosserat_bench).
///
/// The non-symmetric addition carries the load stiffness of follower loads at the last node
/// (the rod's free end): eliminating the chain in node order leaves that block for the end, so
/// the last Schur complement S_N + U is factored by LU with partial pivoting and the whole solve
/// stays exact, with no iteration or low-rank update.
///
/// Supported (fixed) degrees of freedom are eliminated as identity rows and columns at
/// Factorize(): the solution is zero there, and the rest is exactly the reduced system's.
/// Eigen's idiom: Factorize(), info(), SolveInPlace(). Neither allocates.
class BlockTridiagonalSystem {
 public:
  static constexpr int kBlockSize = 6;
  using Block = Eigen::Matrix<double, kBlockSize, kBlockSize>;
  using BlockVector = Eigen::Matrix<double, kBlockSize, 1>;

  BlockTridiagonalSystem() = default;
  /// `fixed[i]` has bit k set when degree of freedom k of node i is held.
  explicit BlockTridiagonalSystem(std::vector<std::uint8_t> fixed)
      : fixed_(std::move(fixed)),
        diagonal_(fixed_.size(), Block::Zero()),
        lower_(fixed_.size(), Block::Zero()),
        inverse_(fixed_.size(), Block::Zero()),
        gain_(fixed_.size(), Block::Zero()) {}

  int BlockCount() const { return static_cast<int>(fixed_.size()); }
  int size() const { return kBlockSize * BlockCount(); }

  /// K_ii (both triangles).
  Block& Diagonal(int i) { return diagonal_[i]; }
  const Block& Diagonal(int i) const { return diagonal_[i]; }
  /// K_(i+1),i; K_i,(i+1) is its transpose.
  Block& Lower(int i) { return lower_[i]; }
  const Block& Lower(int i) const { return lower_[i]; }
  /// U, added to the last diagonal block only: the non-symmetric part of the matrix.
  Block& LastUnsymmetric() { return last_unsymmetric_; }

  /// Factors the matrix (after imposing the supports on it). kNotPositiveDefinite when a pivot
  /// falls below 64 eps of its diagonal entry (the structure is not supported against a rigid
  /// motion, or is past a stability limit), or when the last block is singular; kNonFinite when
  /// a NaN or infinity turns up.
  Status Factorize() {
    ImposeSupports();
    const int n = BlockCount();
    status_ = Status::kOk;
    unsymmetric_ = !last_unsymmetric_.isZero(0.0);
    Block s = diagonal_[0];
    for (int i = 0; i < n; ++i) {
      if (i == n - 1 && unsymmetric_) {
        s += last_unsymmetric_;
        last_lu_.compute(s);
        const auto pivots = last_lu_.matrixLU().diagonal().cwiseAbs();
        if (!pivots.allFinite()) return status_ = Status::kNonFinite;
        if (!(pivots.minCoeff() > kPivotFloor * s.cwiseAbs().maxCoeff())) {
          return status_ = Status::kNotPositiveDefinite;
        }
        break;
      }
      status_ = EliminateNode(i, s);
      if (status_ != Status::kOk) return status_;
    }
    return status_;
  }

  Status info() const { return status_; }

  /// Solves K x = b in place (zero at the supports). Call only when info() is kOk.
  void SolveInPlace(Eigen::Ref<Eigen::VectorXd> b) const {
    const int n = BlockCount();
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k < kBlockSize; ++k) {
        if (fixed_[i] & (1u << k)) b[kBlockSize * i + k] = 0.0;
      }
    }
    for (int i = 1; i < n; ++i) {  // z_i = b_i - G_(i-1) z_(i-1)
      b.segment<kBlockSize>(kBlockSize * i).noalias() -=
          gain_[i - 1] * b.segment<kBlockSize>(kBlockSize * (i - 1));
    }
    BlockVector x;
    for (int i = n - 1; i >= 0; --i) {  // x_i = S_i^-1 z_i - G_i^T x_(i+1)
      if (i == n - 1 && unsymmetric_) {
        x = last_lu_.solve(b.segment<kBlockSize>(kBlockSize * i));
      } else {
        x.noalias() = inverse_[i] * b.segment<kBlockSize>(kBlockSize * i);
        if (i + 1 < n) {
          x.noalias() -= gain_[i].transpose() * b.segment<kBlockSize>(kBlockSize * (i + 1));
        }
      }
      b.segment<kBlockSize>(kBlockSize * i) = x;
    }
  }

  /// The matrix as it stands (supports imposed only after Factorize()), for tests.
  Eigen::MatrixXd ToDense() const {
    const int n = BlockCount();
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(size(), size());
    for (int i = 0; i < n; ++i) {
      k.block<kBlockSize, kBlockSize>(kBlockSize * i, kBlockSize * i) = diagonal_[i];
      if (i + 1 < n) {
        k.block<kBlockSize, kBlockSize>(kBlockSize * (i + 1), kBlockSize * i) = lower_[i];
        k.block<kBlockSize, kBlockSize>(kBlockSize * i, kBlockSize * (i + 1)) =
            lower_[i].transpose();
      }
    }
    k.bottomRightCorner<kBlockSize, kBlockSize>() += last_unsymmetric_;
    return k;
  }

 private:
  // A pivot this far below its diagonal entry is round-off of a singular matrix (as in
  // BandCholesky).
  static constexpr double kPivotFloor = 64.0 * std::numeric_limits<double>::epsilon();

  // Identity rows and columns for the fixed degrees of freedom.
  void ImposeSupports() {
    const int n = BlockCount();
    for (int i = 0; i < n; ++i) {
      if (fixed_[i] == 0) continue;
      for (int k = 0; k < kBlockSize; ++k) {
        if (!(fixed_[i] & (1u << k))) continue;
        diagonal_[i].row(k).setZero();
        diagonal_[i].col(k).setZero();
        diagonal_[i](k, k) = 1.0;
        if (i + 1 < n) lower_[i].col(k).setZero();
        if (i > 0) lower_[i - 1].row(k).setZero();
        if (i == n - 1) {
          last_unsymmetric_.row(k).setZero();
          last_unsymmetric_.col(k).setZero();
        }
      }
    }
  }

  // s -= g k^T (both 6 x 3). EliminateNode reads only the lower triangle of S (with the whole
  // lower-left 3 x 3 block), so unless `full` only the columns' parts from the diagonal down
  // (rounded to whole packets: 24 of the 36 entries) are formed.
  using Columns = Eigen::Matrix<double, kBlockSize, 3>;
  static void SubtractProduct(const Columns& g, const Columns& k, bool full, Block& s) {
    if (full) {
      s.noalias() -= g * k.transpose();
      return;
    }
    s.leftCols<2>().noalias() -= g * k.topRows<2>().transpose();
    s.block<4, 2>(2, 2).noalias() -= g.middleRows<4>(2) * k.middleRows<2>(2).transpose();
    s.block<2, 2>(4, 4).noalias() -= g.bottomRows<2>() * k.bottomRows<2>().transpose();
  }

  // The inverse of the symmetric 3 x 3 matrix a (lower triangle read) by cofactors, after
  // checking the pivots of its LDL^T (leading minors over their predecessors) against
  // `reference` (diagonal entries).
  template <typename Matrix>
  static Status InvertSymmetric(const Matrix& a, const Eigen::Vector3d& reference,
                                Eigen::Matrix3d& inverse) {
    const double c00 = a(1, 1) * a(2, 2) - a(2, 1) * a(2, 1);
    const double c10 = a(2, 0) * a(2, 1) - a(1, 0) * a(2, 2);
    const double c20 = a(1, 0) * a(2, 1) - a(2, 0) * a(1, 1);
    const double minor2 = a(0, 0) * a(1, 1) - a(1, 0) * a(1, 0);
    const double det = a(0, 0) * c00 + a(1, 0) * c10 + a(2, 0) * c20;
    if (!std::isfinite(det)) return Status::kNonFinite;
    if (!(a(0, 0) > kPivotFloor * reference[0]) ||
        !(minor2 > kPivotFloor * reference[1] * a(0, 0)) ||
        !(det > kPivotFloor * reference[2] * minor2)) {
      return Status::kNotPositiveDefinite;
    }
    const double r = 1.0 / det;
    inverse(0, 0) = r * c00;
    inverse(1, 0) = inverse(0, 1) = r * c10;
    inverse(2, 0) = inverse(0, 2) = r * c20;
    inverse(1, 1) = r * (a(0, 0) * a(2, 2) - a(2, 0) * a(2, 0));
    inverse(2, 1) = inverse(1, 2) = r * (a(1, 0) * a(2, 0) - a(0, 0) * a(2, 1));
    inverse(2, 2) = r * minor2;
    return Status::kOk;
  }

  // Eliminates node i, whose Schur complement S = [A B^T; B C] is `s` (lower triangle read), and
  // leaves the next node's in `s`. With X = B A^-1 and T = C - X B^T,
  //   S^-1 = [A^-1 + X^T T^-1 X, -X^T T^-1; -T^-1 X, T^-1],
  // and with K = K_(i+1),i = [K1 K2] by 3 columns, Z = K2 - K1 X^T and W = Z T^-1,
  //   G = K S^-1 = [K1 A^-1 - W X, W],  K S^-1 K^T = (K1 A^-1) K1^T + W Z^T.
  // The pivots are those of S's LDL^T, each checked against its diagonal entry. The next
  // complement is formed from these 6 x 3 pieces rather than as G K^T: (K1 A^-1) K1^T needs
  // only A^-1, and the rest waits for T^-1 alone, not for S^-1 and G, which the solve needs but
  // the next node does not. That shortens the chain of dependent operations from node to node,
  // which sets the pace here (doc/speed.md).
  Status EliminateNode(int i, Block& s) {
    const BlockVector reference = diagonal_[i].diagonal();
    Eigen::Matrix3d a_inverse, t_inverse;
    Status status = InvertSymmetric(s.topLeftCorner<3, 3>(), reference.head<3>(), a_inverse);
    if (status != Status::kOk) return status;
    const Eigen::Matrix3d b = s.bottomLeftCorner<3, 3>();
    const Eigen::Matrix3d x = b * a_inverse;
    const Eigen::Matrix3d t = s.bottomRightCorner<3, 3>() - x * b.transpose();
    status = InvertSymmetric(t, reference.tail<3>(), t_inverse);
    if (status != Status::kOk) return status;
    const int n = BlockCount();
    if (i + 1 < n) {
      const Block& k = lower_[i];
      const Columns k1 = k.leftCols<3>();
      const Columns v = k1 * a_inverse;  // K1 A^-1
      const Columns z = k.rightCols<3>() - k1 * x.transpose();
      const Columns w = z * t_inverse;
      const bool full = i + 1 == n - 1 && unsymmetric_;
      s = diagonal_[i + 1];
      SubtractProduct(v, k1, full, s);
      SubtractProduct(w, z, full, s);
      gain_[i].leftCols<3>().noalias() = v - w * x;
      gain_[i].rightCols<3>() = w;
    }
    const Eigen::Matrix3d y = t_inverse * x;  // T^-1 X
    Block& inverse = inverse_[i];
    // By coefficients: as a sum with the product X^T Y, Eigen evaluates this through an
    // out-of-line call per coefficient.
    for (int col = 0; col < 3; ++col) {
      for (int row = 0; row < 3; ++row) {
        inverse(row, col) = a_inverse(row, col) + x.col(row).dot(y.col(col));
      }
    }
    inverse.bottomLeftCorner<3, 3>() = -y;
    inverse.topRightCorner<3, 3>() = -y.transpose();
    inverse.bottomRightCorner<3, 3>() = t_inverse;
    return Status::kOk;
  }

  std::vector<std::uint8_t> fixed_;
  std::vector<Block> diagonal_, lower_;
  std::vector<Block> inverse_;  // S_i^-1
  std::vector<Block> gain_;     // G_i = K_(i+1),i S_i^-1
  Block last_unsymmetric_ = Block::Zero();
  Eigen::PartialPivLU<Block> last_lu_;
  bool unsymmetric_ = false;
  Status status_ = Status::kNotPositiveDefinite;
};

}  // namespace cosmems
