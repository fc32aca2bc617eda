#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

#include "cosmems/linalg/band_cholesky.hpp"

namespace cosmems {

/// The inelastic impact of points on the substrate: the velocity and the acceleration of the
/// held points (those touching and moving into it, every stuck one) removed by the projection
/// that is orthogonal in the mass metric, x -= M^-1 C^T (C M^-1 C^T)^-1 C x, which can only lower
/// the kinetic energy (C the held points' rows, their motion toward the substrate's normal).
/// M^-1 C^T is kept column by column, each point's solved the first time it is held: M is the
/// owner's one mass factor, the same at every call, and a solve per held point whenever the held
/// set changed cost 42 % of a 1000-element folded flexure's haptic run while its shuttle lay stuck
/// (points touching the substrate join and leave the set as their velocity turns). The factor of
/// C M^-1 C^T depends on the held set: a zone held step after step reuses it. Held points may be
/// dependent (a rigid plate lying on its four corners has three motions normal to the substrate; a
/// beam's node held with the points beside it): the factor then skips each row whose pivot is lost
/// to round-off against its diagonal (it is a combination of the rows before it), and the
/// projection is onto the motions that keep every held point still, as with independent rows. Sized
/// once for `rows` points of a model of `size` unknowns (a column for each); Project() allocates
/// nothing.
class ImpactProjection {
 public:
  ImpactProjection(Eigen::Index size, Eigen::Index rows)
      : columns_(Eigen::MatrixXd::Zero(size, rows)),
        solved_(static_cast<std::size_t>(rows), 0),
        schur_(Eigen::MatrixXd::Zero(rows, rows)),
        multipliers_(Eigen::VectorXd::Zero(rows)),
        held_set_(static_cast<std::size_t>(rows), 0),
        kept_(static_cast<std::size_t>(rows), 0) {}

  /// Projects v and a. `held` lists the `count` held points by index; `row(k, column)` writes
  /// point k's row into the zeroed `column`, `along(k, x)` is its motion C_k x. `mass` must be
  /// the same factor at every call.
  template <class Row, class Along>
  void Project(const BandCholesky& mass, const std::vector<int>& held, int count, Row row,
               Along along, Eigen::VectorXd& v, Eigen::VectorXd& a) {
    if (count == 0 || mass.info() != Status::kOk) return;
    if (count != held_ || !std::equal(held.begin(), held.begin() + count, held_set_.begin())) {
      held_ = 0;
      for (int j = 0; j < count; ++j) {
        const auto k = static_cast<std::size_t>(held[j]);
        auto column = columns_.col(held[j]);
        if (!solved_[k]) {
          column.setZero();
          row(held[j], column);
          mass.SolveInPlace(column);
          solved_[k] = 1;
        }
        for (int i = 0; i < count; ++i) schur_(i, j) = along(held[i], column);
      }
      if (!Factor(count)) return;
      std::copy(held.begin(), held.begin() + count, held_set_.begin());
      held_ = count;
    }
    for (Eigen::VectorXd* x : {&v, &a}) {
      auto m = multipliers_.head(count);
      for (int j = 0; j < count; ++j) m[j] = along(held[j], *x);
      Solve(count, m);
      for (int j = 0; j < count; ++j) {
        if (m[j] != 0.0) x->noalias() -= m[j] * columns_.col(held[j]);
      }
    }
  }

 private:
  // The lower Cholesky factor of schur_'s leading block in place, column by column, each row
  // whose pivot falls below 1e-10 of its diagonal skipped (kept_ says which); false when no row
  // is kept or a pivot is not finite.
  bool Factor(int count) {
    bool any = false;
    for (int j = 0; j < count; ++j) {
      double pivot = schur_(j, j);
      for (int k = 0; k < j; ++k) {
        if (kept_[k]) pivot -= schur_(j, k) * schur_(j, k);
      }
      if (!std::isfinite(pivot)) return false;
      kept_[j] = pivot > 1e-8 * schur_(j, j);
      if (!kept_[j]) continue;
      any = true;
      const double root = std::sqrt(pivot);
      schur_(j, j) = root;
      for (int i = j + 1; i < count; ++i) {
        double sum = schur_(i, j);
        for (int k = 0; k < j; ++k) {
          if (kept_[k]) sum -= schur_(i, k) * schur_(j, k);
        }
        schur_(i, j) = sum / root;
      }
    }
    return any;
  }

  // m = (L L^T)^-1 m over the kept rows; the skipped rows' multipliers are zero.
  void Solve(int count, Eigen::Ref<Eigen::VectorXd> m) const {
    for (int j = 0; j < count; ++j) {
      if (!kept_[j]) {
        m[j] = 0.0;
        continue;
      }
      for (int k = 0; k < j; ++k) {
        if (kept_[k]) m[j] -= schur_(j, k) * m[k];
      }
      m[j] /= schur_(j, j);
    }
    for (int j = count - 1; j >= 0; --j) {
      if (!kept_[j]) continue;
      for (int i = j + 1; i < count; ++i) {
        if (kept_[i]) m[j] -= schur_(i, j) * m[i];
      }
      m[j] /= schur_(j, j);
    }
  }

  Eigen::MatrixXd columns_;   ///< M^-1 C_k^T in column k, where solved_[k]
  std::vector<char> solved_;  ///< the points whose column is made
  Eigen::MatrixXd schur_;
  Eigen::VectorXd multipliers_;
  std::vector<int> held_set_;  ///< the held points schur_ was made for
  int held_ = 0;               ///< their count (0: none made)
  std::vector<char> kept_;     ///< the rows the factor keeps
};

}  // namespace cosmems
