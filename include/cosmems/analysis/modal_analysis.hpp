#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/analysis/mode_kind.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/core/constants.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"

namespace cosmems {

namespace internal {

/// The Rayleigh functional of a symmetric polynomial eigenproblem: the root l near `estimate`
/// of z^T (Kr - sum_j l^(j+1) Mr_j) z = 0, by Newton. Its error is quadratic in the error of z,
/// so it removes the round-off that the nonsymmetric companion solve leaves in l.
double RayleighFunctional(const Eigen::MatrixXd& kr, const std::vector<Eigen::MatrixXd>& mr,
                          const Eigen::Ref<const Eigen::VectorXd>& z, double estimate);

/// Solves the projected problem (Kr - sum_j l^(j+1) Mr_j) z = 0 for its `wanted` lowest roots.
///
/// All q Ritz pairs of the order-0 pencil (Kr, Mr_0) come first; they are the answer at order 0
/// and the guard vectors and starting points otherwise. For order >= 1 each wanted root then
/// follows a nonlinear Rayleigh-quotient iteration from its order-0 pair: take the eigenvector of
/// the symmetric matrix P(l) that is closest to the current vector, move l to its Rayleigh
/// functional, repeat. The vector is followed by its direction, not by the index of its
/// eigenvalue in P(l): the minmax index (Voss & Werner) holds only where every vector has a
/// Rayleigh functional, and the truncated series breaks that for the vectors of modes beyond
/// what the elements resolve, which shifted the index of an axial mode among the bending ones
/// (it was measured to lose the second axial mode of a 40-element cantilever at order 1, and to
/// leave modes 1-4 of an 8-element one unsettled at orders 2-3). The roots are then sorted, and
/// two that reached the same vector count as not settled. (A companion linearisation was
/// measured to lose physical roots from order 3 on: its blocks span many decades and the
/// nonsymmetric solve turned real roots complex.)
/// Returns false when a wanted root did not settle within the iteration limit.
bool SolveProjected(const Eigen::MatrixXd& kr, const std::vector<Eigen::MatrixXd>& mr, int wanted,
                    Eigen::VectorXd& lambda, Eigen::MatrixXd& z);

}  // namespace internal

struct ModalOptions {
  int count = 4;             ///< modes wanted, lowest first
  double tolerance = 1e-12;  ///< relative change of every wanted eigenvalue between sweeps
  /// ||K x - sum_j l^(j+1) M_2j x|| <= residual_tolerance * l ||M_0 x|| for every wanted mode:
  /// vectors converge half as fast as eigenvalues, and modal dynamics needs them.
  double residual_tolerance = 1e-10;
  int max_iterations = 500;  ///< sweeps before giving up with Status::kNotConverged
};

struct Mode {
  double frequency_hz = 0.0;
  ModeKind kind = ModeKind::kBendingY;
  Eigen::VectorXd shape;  ///< reduced, internal units, x^T M_0 x = 1, largest entry positive
};

/// Status::kNotConverged at series order >= 1 usually means modes were asked for beyond what the
/// mesh resolves: where an element's frequency parameter rho A l^4 w^2 / EI passes 4.73^4 (its
/// first clamped-clamped frequency) the power series diverges and the truncated polynomial has
/// no real root to find. The modes below are still returned.
struct ModalResult {
  Status status = Status::kOk;
  std::vector<Mode> modes;  ///< ascending frequency
  int iterations = 0;
};

/// The matrices of a modal problem, D(w) = K - sum_j w^(2j+2) M_j, with K a band plus an optional
/// rank-one part s u u^T (internal units).
struct ModalPencil {
  SymmetricBandMatrix stiffness;
  double rank_one_scale = 0.0;
  Eigen::VectorXd rank_one;
  std::vector<SymmetricBandMatrix> mass;

  /// About the straight beam: the model's (prestressed) stiffness and mass terms.
  template <int Dim>
  static ModalPencil Straight(const BeamModel<Dim>& model) {
    ModalPencil pencil{model.Stiffness(), 0.0, Eigen::VectorXd::Zero(model.FreeDofCount()), {}};
    for (int j = 0; j <= model.SeriesOrder(); ++j) pencil.mass.push_back(model.Mass(j));
    return pencil;
  }

  /// About a deflected equilibrium d of a stretching beam: the force's tangent joins the
  /// stiffness, and the axial force it adds to the model's own enters the frequency terms as
  /// -N G_(j+1).
  template <int Dim>
  static ModalPencil About(const BeamModel<Dim>& model, StretchingForce<Dim>& force,
                           const Eigen::VectorXd& d) {
    const int n = model.FreeDofCount();
    ForceTangent tangent(n, model.Stiffness().bandwidth());
    tangent.Clear();
    Eigen::VectorXd r = Eigen::VectorXd::Zero(n);
    force.Evaluate(d, r, tangent);
    const double extra = force.AxialForce(d) - model.AxialLoad();
    ModalPencil pencil = Straight(model);
    pencil.stiffness.mutable_data() += tangent.band().data();
    pencil.rank_one_scale = tangent.rank_one_scale();
    pencil.rank_one = tangent.rank_one_vector();
    for (int j = 0; j < model.SeriesOrder(); ++j) {
      pencil.mass[j].mutable_data() -= extra * model.Geometric(j + 1).data();
    }
    return pencil;
  }

  Eigen::MatrixXd DenseStiffness() const;
};

namespace internal {

/// The sweeps of SolveModal for q < n / 2 vectors; returns the status and fills the Ritz
/// values `lambda`, vectors `x` (n x q) and the sweep count.
Status SubspaceIteration(const ModalPencil& pencil, const BandRankOneCholesky& cholesky,
                         const ModalOptions& options, int p, int q, Eigen::VectorXd& lambda,
                         Eigen::MatrixXd& x, int& iterations);

}  // namespace internal

/// The lowest natural frequencies and modes of a beam.
///
/// Order 0 solves K x = w^2 M_0 x. Order k >= 1 solves the polynomial eigenproblem
/// (K - l M_0 - l^2 M_2 - ... - l^(k+1) M_2k) x = 0 in l = w^2 of the power-series elements.
/// Both go by subspace iteration with Rayleigh-Ritz: each sweep applies K^-1 (one band back-
/// solve per vector) to sum_j l_i^j M_2j x_i, the fixed point of x = l K^-1 sum_j l^j M_2j x, then
/// projects onto the swept basis and solves the small projected problem (internal::SolveProjected).
/// Mode i converges as l_i / l_(q+1) per sweep with q = max(2p, p + 8) vectors.
///
/// This is the pencil's part, whatever structure it came from: `time_unit` (s) turns its
/// eigenvalues into frequencies, and each mode's kind is left for the structure to classify.
ModalResult SolvePencilModes(const ModalPencil& pencil, double time_unit,
                             const ModalOptions& options = {});

/// The modes of a beam about the state the pencil describes, each classified by its field.
template <int Dim>
ModalResult SolveModal(const BeamModel<Dim>& model, const ModalPencil& pencil,
                       const ModalOptions& options = {}) {
  ModalResult result = SolvePencilModes(pencil, model.units().time, options);
  for (Mode& mode : result.modes) mode.kind = ClassifyMode(model, mode.shape);
  return result;
}

/// The modes about the straight (prestressed) beam.
template <int Dim>
ModalResult SolveModal(const BeamModel<Dim>& model, const ModalOptions& options = {}) {
  return SolveModal(model, ModalPencil::Straight(model), options);
}

}  // namespace cosmems
