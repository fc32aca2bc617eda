#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/linalg/band_ldlt.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/time/modal_model.hpp"
#include "cosmems/time/mode_step.hpp"
#include "cosmems/time/newton_driver.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

/// Modal propagation with a nonlinear force (contact and stiction, the surface pressures,
/// mid-plane stretching): M a + C v + K d + r(d) = P s, the k modes of a ModalModel propagated
/// exactly and the truncated ones answering statically, d = Phi q + R (P s - r(d)) with
/// R = K^-1 - Phi diag(1/w^2) Phi^T (ModalModel::ResidualFlexibility).
///
/// The loads P s vary linearly over a step, as in ModalPropagator. The force is held over each
/// step at its value at the step's end: per mode [q, q']_(n+1) = free motion - (b0 + b1) phi^T r
/// (ModeStep), so the end displacement solves d + G r(d) = d_free with
/// G = R + Phi diag((b0 + b1)_q) Phi^T, which Newton solves in the symmetric form
///   G^-1 (d - d_free) + r(d) = 0,  J = G^-1 + dr/dd.
/// G^-1 is the step's own stiffness: about 2/h^2 times the modal mass along the modes, K across
/// the truncated ones; so a contact holds the beam between the modes as the static correction
/// would, and the state at rest is the full model's static equilibrium K d + r(d) = P s.
///
/// Why held, not interpolated like the loads: a reaction interpolated from r_n to r_(n+1) enters
/// the end displacement as b0 r_n + b1 r_(n+1), with b0 twice b1 for short steps, so the reaction
/// holding a node on the substrate must be -2 times the last one at every step, and it diverges.
/// Held, the last step's reaction does not enter the next (the time stepping of Moreau and Jean
/// for constraints): first order in how the force varies over a step, while the linear part stays
/// exact. At the end of a step the force removes the motion it forbids
/// (NonlinearForce::ProjectMotion) from v = Phi q', and q' is fitted back in the M_0 norm; both
/// projections are orthogonal in the mass metric, so neither adds kinetic energy.
///
/// Newton follows NewtonDriver's protocol, as the Newmark path does: the force's Settle() after
/// convergence, Revert() after a failure, J's factor kept while it serves, a mass term raised
/// where J turns indefinite (a Casimir or electrostatic snap), an iterate outside the force's
/// domain pulled back, and a failed step cut into halves up to NewtonOptions::max_cuts deep.
///
/// G and J are never formed, so the path scales with the mesh as the band path does. By R's
/// definition G = K^-1 + Phi E Phi^T, E = diag((b0 + b1)_q - 1/w^2), and by Woodbury
///   G^-1 = K - U D U^T,  U = K Phi,  D = (E^-1 + Phi^T K Phi)^-1 (k x k, one per step length),
/// so J = B + V C V^T with the band B = K + the force's band tangent (+ a mass term, below),
/// V = [U, u] (u the force's rank-one vector) and C = diag(-D, s). A factorisation factors B,
/// solves it for V's k + 1 columns Z = B^-1 V and factors the capacitance S = C^-1 + V^T Z
/// ((k + 1)^2); a solve is B's back-solve and products with Z. J's definiteness comes from the
/// inertias (Haynsworth): its negative eigenvalues number neg(B) + pos(S) - pos(C), B factored
/// with its inertia where it is not definite (a Casimir pressure stiffer than K along a soft
/// mode, which the modes' own stiffness holds). The same count on G^-1 = K + U (-D) U^T, whose
/// S is -E^-1, checks the set-up. Velocity-dependent forces are refused (the modes carry their
/// damping as ratios). Steps allocate nothing.
class NonlinearModalIntegrator {
 public:
  /// `modal`: the modes of `model` (a BeamModel or a FrameModel); `patterns`: n x m load
  /// patterns.
  template <class Model>
  NonlinearModalIntegrator(const Model& model, const ModalModel& modal,
                           const Eigen::MatrixXd& patterns, NonlinearForce& force, double time_step,
                           NewtonOptions options = {})
      : force_(force),
        shapes_(modal.shapes),
        modal_loads_(modal.shapes.transpose() * patterns),
        residual_loads_(modal.ResidualFlexibility(model, patterns)),
        stiffness_(model.Stiffness()),
        mass_(model.Mass(0)),
        stiffness_factor_(model.Stiffness()),
        dt_(time_step),
        newton_((ValidateNewtonOptions(options), options)),
        tangent_(model.FreeDofCount(), model.Mass(0).bandwidth()) {
    RequirePositive("time_step", time_step);
    if (force.HasViscousPart()) {
      throw std::invalid_argument(
          "modal propagation carries damping as modal ratios: a velocity-dependent force (a gas "
          "film) needs a Newmark-family integrator");
    }
    const int n = model.FreeDofCount();
    const Eigen::Index k = shapes_.cols();
    for (const ModalCoordinate& mode : modal.coordinates) RequirePositive("mode omega", mode.omega);
    if (stiffness_factor_.info() != Status::kOk) setup_status_ = stiffness_factor_.info();
    fit_ = modal.Fit(model);
    inverse_w2_.resize(k);
    coupling_.resize(n, k);
    for (Eigen::Index i = 0; i < k; ++i) {
      const double w = modal.coordinates[static_cast<std::size_t>(i)].omega;
      inverse_w2_[i] = 1.0 / (w * w);
      stiffness_.Multiply(shapes_.col(i), coupling_.col(i));
    }
    abs_coupling_ = coupling_.cwiseAbs();
    const Eigen::MatrixXd modal_stiffness = shapes_.transpose() * coupling_;  // Phi^T K Phi
    // The step's map and G^-1's low-rank part for the step and each of its cuts.
    for (int depth = 0; depth <= options.max_cuts; ++depth) {
      const double h = std::ldexp(dt_, -depth);
      Level level;
      level.held.resize(k);
      Eigen::VectorXd e(k);
      for (Eigen::Index i = 0; i < k; ++i) {
        const ModalCoordinate& mode = modal.coordinates[static_cast<std::size_t>(i)];
        level.steps.push_back(ModeStep::Make(mode, h));
        const ModeStep& m = level.steps.back();
        level.held[i] = std::max(m.b0[0] + m.b1[0], kHeldFloor / (mode.omega * mode.omega));
        // A mode the held force moves exactly as far as statically adds nothing to K^-1: within
        // a hair of it, kHeldFloor of its static response stands in (E^-1 stays finite).
        e[i] = level.held[i] - inverse_w2_[i];
        if (std::abs(e[i]) < kHeldFloor * inverse_w2_[i]) {
          e[i] = std::copysign(kHeldFloor * inverse_w2_[i], e[i]);
        }
      }
      level.d_inverse = modal_stiffness;
      level.d_inverse.diagonal() += e.cwiseInverse();
      const Eigen::LDLT<Eigen::MatrixXd> ldlt(level.d_inverse);
      level.negative_d = static_cast<int>((ldlt.vectorD().array() < 0.0).count());
      level.d = ldlt.solve(Eigen::MatrixXd::Identity(k, k));
      level.d = 0.5 * (level.d + level.d.transpose()).eval();
      level.abs_d = level.d.cwiseAbs();
      // G^-1's negative eigenvalues: neg(K) + neg(E) - neg(E^-1 + Phi^T K Phi).
      const int negative_e = static_cast<int>((e.array() < 0.0).count());
      if (ldlt.info() != Eigen::Success || negative_e != level.negative_d) {
        setup_status_ = Status::kNotPositiveDefinite;
      }
      levels_.push_back(std::move(level));
    }
    const int bandwidth =
        std::max({stiffness_.bandwidth(), mass_.bandwidth(), tangent_.band().bandwidth()});
    band_ = SymmetricBandMatrix(n, bandwidth);
    (void)band_factor_.Compute(band_);  // sizes the factors' buffers now
    (void)band_inertia_.Compute(band_);
    columns_.setZero(n, k + 1);
    columns_.leftCols(k) = coupling_;
    solved_columns_.setZero(n, k + 1);
    capacitance_.setZero(k + 1, k + 1);
    capacitance_factor_.compute(Eigen::MatrixXd::Identity(k + 1, k + 1));
    for (Eigen::VectorXd* v :
         {&d_, &velocity_, &scratch_, &d_new_, &d_free_, &y_free_, &r_, &residual_, &work_,
          &correction_, &d_save_, &correction_save_, &magnitude_}) {
      v->setZero(n);
    }
    for (Eigen::VectorXd* v : {&q_, &qdot_, &q_free_, &qdot_free_, &g_from_, &g_to_, &rho_,
                               &q_save_, &qdot_save_, &modal_a_, &modal_b_}) {
      v->setZero(k);
    }
    capacitance_rhs_.setZero(k + 1);
    capacitance_solution_.setZero(k + 1);
    s_.setZero(patterns.cols());
    s_from_.setZero(patterns.cols());
    s_to_.setZero(patterns.cols());
  }

  /// The state d0, v0 under the load amplitudes s0 at t = 0. The modal coordinates are fitted to
  /// it in the M_0 norm (ModalModel::Fit), of d0 less its static part R (P s0 - r(d0)).
  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& s0) {
    RequireSize("d0", d0.size(), d_.size(), "one per free unknown");
    RequireSize("v0", v0.size(), d_.size(), "one per free unknown");
    RequireSize("s0", s0.size(), s_.size(), "one per load pattern");
    d_ = d0;
    s_ = s0;
    time_ = 0.0;
    newton_.ForgetFactor();
    r_.setZero();
    tangent_.Clear();
    if (!force_.Evaluate(d_, r_, tangent_)) return Status::kNonFinite;
    ResidualFlexibility(r_, scratch_);
    work_ = d0 - residual_loads_ * s0 + scratch_;
    q_.noalias() = fit_ * work_;
    qdot_.noalias() = fit_ * v0;
    velocity_.noalias() = shapes_ * qdot_;
    // What the force holds the state away from its free motion by: the first predictor.
    correction_ = d0 - residual_loads_ * s0;
    correction_.noalias() -= shapes_ * q_;
    force_.Commit(d_);
    return setup_status_;
  }

  /// Advances by dt to the load amplitudes s_next. On failure the state stays at the step's start.
  [[nodiscard]] Status Step(const Eigen::VectorXd& s_next) {
    if (setup_status_ != Status::kOk) return setup_status_;
    s_target_ = &s_next;
    newton_.stats() = {};
    time_save_ = time_;
    auto substep = [this](double a, double b, int level) { return Substep(a, b, level); };
    auto save = [this] {
      q_save_ = q_;
      qdot_save_ = qdot_;
      d_save_ = d_;
      correction_save_ = correction_;
    };
    const Status status = newton_.AdvanceInHalves(substep, save, [this] { force_.Revert(); });
    if (status == Status::kOk) {
      s_ = s_next;
    } else if (newton_.stats().cuts > 0) {  // a cut step may have got part of the way: back
      q_ = q_save_;
      qdot_ = qdot_save_;
      d_ = d_save_;
      correction_ = correction_save_;
      velocity_.noalias() = shapes_ * qdot_;
      time_ = time_save_;
    }
    s_target_ = nullptr;
    return status;
  }

  const Eigen::VectorXd& displacement() const { return d_; }
  /// Phi q': the modes' velocity (the static part's rate is not tracked).
  const Eigen::VectorXd& velocity() const { return velocity_; }
  const Eigen::VectorXd& modal_displacement() const { return q_; }
  const Eigen::VectorXd& modal_velocity() const { return qdot_; }
  double time() const { return time_; }
  /// What the last step cost (all its sub-steps).
  const NewtonStats& last_stats() const { return newton_.stats(); }

 private:
  friend class NewtonDriver;

  // The modes' maps over a step of dt / 2^depth and the low-rank part of that step's stiffness
  // G^-1 = K - U D U^T.
  struct Level {
    std::vector<ModeStep> steps;
    Eigen::VectorXd held;  ///< how far a unit force held over the step moves each mode
    Eigen::MatrixXd d, d_inverse, abs_d;
    int negative_d = 0;  ///< D's negative eigenvalues
  };

  // A force held over a whole number of an undamped mode's periods leaves that mode where it
  // would be without it, (b0 + b1)_q = (1 - cos w h) / w^2 = 0, and G turns singular: within a
  // hair of such a step the mode is moved by kHeldFloor of its static response instead, an error
  // of that size in that mode alone (tested with the step equal to the first period).
  static constexpr double kHeldFloor = 1e-6;

  // One step over [from, to] of the step (dt / 2^depth long), the loads interpolated linearly.
  Status Substep(double from, double to, int depth) {
    const Level& level = levels_[static_cast<std::size_t>(depth)];
    s_from_ = (1.0 - from) * s_ + from * *s_target_;
    s_to_ = (1.0 - to) * s_ + to * *s_target_;
    g_from_.noalias() = modal_loads_ * s_from_;
    g_to_.noalias() = modal_loads_ * s_to_;
    for (Eigen::Index i = 0; i < q_.size(); ++i) {  // the free motion of each mode
      const ModeStep& m = level.steps[static_cast<std::size_t>(i)];
      const Eigen::Vector2d y =
          m.a * Eigen::Vector2d(q_[i], qdot_[i]) + m.b0 * g_from_[i] + m.b1 * g_to_[i];
      q_free_[i] = y[0];
      qdot_free_[i] = y[1];
    }
    d_free_.noalias() = shapes_ * q_free_;
    d_free_.noalias() += residual_loads_ * s_to_;
    StepStiffness(level, d_free_, y_free_);
    d_new_ = d_free_ + correction_;  // the force holds the beam where it held it last
    const double h = (to - from) * dt_;
    mass_term_ = 2.0 / (h * h);  // a mode's stiffness over the step per unit modal mass
    level_ = &level;
    from_ = from;
    to_ = to;
    // The factor serves the sub-steps of one length: the key is h.
    return newton_.Solve(*this, h);
  }

  // NewtonDriver's scheme: R = G^-1 d - G^-1 d_free + r, and the sizes of its terms.
  bool Evaluate(NewtonResidual& out) {
    r_.setZero();
    tangent_.Clear();
    if (!force_.Evaluate(d_new_, r_, tangent_)) return false;
    StepStiffness(*level_, d_new_, work_);
    residual_ = work_ - y_free_ + r_;
    out.norm = residual_.norm();
    out.reference = work_.norm() + y_free_.norm() + r_.norm();
    return true;
  }

  // Back along the last correction, which residual_ still holds (d = previous - correction).
  bool Retreat() {
    residual_ *= 0.5;
    d_new_ += residual_;
    return true;
  }
  // The prediction outside the force's domain: the step's start instead.
  bool BackToStart() {
    d_new_ = d_;
    return true;
  }
  // A kept factor's correction is never undone here (NewtonDriver): undone on the pressed
  // resonator's landing (8 modes, contact and stiction), the fresh factor where it started was
  // not definite under any mass shift, and the cut step made an 18 ms tick where retreating along
  // the correction takes 2.5 ms (doc/speed.md).
  bool Undo() { return false; }

  // J^-1 R = B^-1 R - Z S^-1 Z^T R, in place in residual_.
  Status SolveKept() {
    capacitance_rhs_.noalias() = solved_columns_.transpose() * residual_;
    if (band_definite_) {
      band_factor_.SolveInPlace(residual_);
    } else {
      band_inertia_.SolveInPlace(residual_);
    }
    capacitance_solution_ = capacitance_factor_.solve(capacitance_rhs_);
    residual_.noalias() -= solved_columns_ * capacitance_solution_;
    return Status::kOk;
  }

  NewtonFactor Factor(double shift) {
    NewtonFactor out;
    out.status = Solve(*level_, shift);
    out.reusable = true;
    return out;
  }

  double MassTerm() const { return mass_term_; }

  NewtonCorrection Update() {
    double increment2 = 0.0, displacement2 = 0.0;
    for (Eigen::Index i = 0; i < d_new_.size(); ++i) {
      d_new_[i] -= residual_[i];
      increment2 += residual_[i] * residual_[i];
      displacement2 += d_new_[i] * d_new_[i];
    }
    NewtonCorrection out;
    out.size = std::sqrt(increment2);
    out.iterate = std::sqrt(displacement2);
    return out;
  }

  bool Settle() { return force_.Settle(d_new_); }

  double RoundOff() { return RoundOff(*level_); }
  // No cheaper bound: the bound itself is formed wherever the tolerance does not end a solve.
  double RoundOffCeiling() const { return std::numeric_limits<double>::infinity(); }

  Status Finish() { return Accept(*level_, from_, to_); }

  // out = G^-1 x = K x - U D U^T x.
  void StepStiffness(const Level& level, const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    stiffness_.Multiply(x, out);
    modal_a_.noalias() = coupling_.transpose() * x;
    modal_b_.noalias() = level.d * modal_a_;
    out.noalias() -= coupling_ * modal_b_;
  }

  // out = R x = K^-1 x - Phi diag(1/w^2) Phi^T x.
  void ResidualFlexibility(const Eigen::VectorXd& x, Eigen::VectorXd& out) {
    out = x;
    stiffness_factor_.SolveInPlace(out);
    modal_a_.noalias() = shapes_.transpose() * x;
    modal_a_ = modal_a_.cwiseProduct(inverse_w2_);
    out.noalias() -= shapes_ * modal_a_;
  }

  // Factors J + shift M_0 = B + V C V^T (see the class comment) and solves J delta = R in place
  // in residual_. With a shift the mass term is that of a shorter step, as in the Newmark path:
  // the iteration creeps the way a shorter step would, solving this step's equations where J
  // itself is indefinite.
  Status Solve(const Level& level, double shift) {
    const Eigen::Index k = shapes_.cols();
    const SymmetricBandMatrix& tangent = tangent_.band();
    Eigen::MatrixXd& b = band_.mutable_data();
    b.setZero();
    b.topRows(stiffness_.bandwidth() + 1) = stiffness_.data();
    b.topRows(tangent.bandwidth() + 1) += tangent.data();
    if (shift != 0.0) b.topRows(mass_.bandwidth() + 1) += shift * mass_.data();
    // The rank-one part as V's last column; without one, a zero column with C's entry 1.
    const double scale = tangent_.rank_one_scale();
    const double c_last = scale != 0.0 ? scale : 1.0;
    if (scale != 0.0) {
      columns_.col(k) = tangent_.rank_one_vector();
    } else {
      columns_.col(k).setZero();
    }
    solved_columns_ = columns_;
    int negative = 0;  // J's negative eigenvalues, by the inertias
    band_definite_ = band_factor_.Compute(band_).info() == Status::kOk;
    if (band_definite_) {
      for (Eigen::Index c = 0; c <= k; ++c) band_factor_.SolveInPlace(solved_columns_.col(c));
    } else {
      if (band_inertia_.Compute(band_) != Status::kOk) return Status::kNotPositiveDefinite;
      negative = band_inertia_.negative_pivots();
      for (Eigen::Index c = 0; c <= k; ++c) band_inertia_.SolveInPlace(solved_columns_.col(c));
    }
    // S = C^-1 + V^T Z, C^-1 = diag(-D^-1, 1 / c_last).
    capacitance_.noalias() = columns_.transpose() * solved_columns_;
    capacitance_.topLeftCorner(k, k) -= level.d_inverse;
    capacitance_(k, k) += 1.0 / c_last;
    capacitance_factor_.compute(capacitance_);
    if (capacitance_factor_.info() != Eigen::Success) return Status::kNotPositiveDefinite;
    const auto pivots = capacitance_factor_.vectorD().array();
    if ((pivots == 0.0).any() || !pivots.isFinite().all()) return Status::kNotPositiveDefinite;
    negative += static_cast<int>((pivots > 0.0).count());
    negative -= level.negative_d + (c_last > 0.0 ? 1 : 0);  // C's positive eigenvalues
    if (negative != 0) return Status::kNotPositiveDefinite;
    return SolveKept();
  }

  // The rounding error of G^-1 d: K d's (SymmetricBandMatrix::ProductRoundOff) and that of the
  // low-rank part, whose entries each sum 2 k + 1 products (Higham 3.5), bounded by
  // |U| |D| |U|^T |d|.
  double RoundOff(const Level& level) {
    const double band = stiffness_.ProductRoundOff(d_new_, scratch_);
    magnitude_ = d_new_.cwiseAbs();
    modal_a_.noalias() = abs_coupling_.transpose() * magnitude_;
    modal_b_.noalias() = level.abs_d * modal_a_;
    magnitude_.noalias() = abs_coupling_ * modal_b_;
    const double mu =
        static_cast<double>(2 * shapes_.cols() + 1) * 0.5 * std::numeric_limits<double>::epsilon();
    return band + mu / (1.0 - mu) * magnitude_.norm();
  }

  // Takes d_new_ and the force r_ there as the end of the sub-step [from, to].
  Status Accept(const Level& level, double from, double to) {
    rho_.noalias() = shapes_.transpose() * r_;
    for (Eigen::Index i = 0; i < q_.size(); ++i) {
      const ModeStep& m = level.steps[static_cast<std::size_t>(i)];
      q_[i] = q_free_[i] - level.held[i] * rho_[i];
      qdot_[i] = qdot_free_[i] - (m.b0[1] + m.b1[1]) * rho_[i];
    }
    correction_ = d_new_ - d_free_;
    d_.swap(d_new_);  // swaps the buffers: allocates nothing
    velocity_.noalias() = shapes_ * qdot_;
    work_ = velocity_;
    scratch_.setZero();  // the force may project an acceleration too; the modes keep none
    force_.ProjectMotion(d_, velocity_, scratch_);
    if (velocity_ != work_) {
      qdot_.noalias() = fit_ * velocity_;
      velocity_.noalias() = shapes_ * qdot_;
    }
    time_ += (to - from) * dt_;
    force_.Commit(d_);
    return Status::kOk;
  }

  NonlinearForce& force_;
  Eigen::MatrixXd shapes_;                   ///< Phi, n x k
  Eigen::MatrixXd modal_loads_;              ///< Phi^T P, k x m
  Eigen::MatrixXd residual_loads_;           ///< R P, n x m
  SymmetricBandMatrix stiffness_;            ///< K
  SymmetricBandMatrix mass_;                 ///< M_0
  BandCholesky stiffness_factor_;            ///< K's, for R
  Eigen::VectorXd inverse_w2_;               ///< 1 / w^2 of each mode
  Eigen::MatrixXd coupling_, abs_coupling_;  ///< U = K Phi and |U|, n x k
  Eigen::MatrixXd fit_;                      ///< (Phi^T M_0 Phi)^-1 Phi^T M_0, k x n
  double dt_;
  NewtonDriver newton_;
  std::vector<Level> levels_;
  Status setup_status_ = Status::kOk;
  ForceTangent tangent_;
  // J's factor: B's (band_factor_ where B is definite, band_inertia_ otherwise), V, Z = B^-1 V
  // and the capacitance S's.
  SymmetricBandMatrix band_;
  BandCholesky band_factor_;
  BandLdlt band_inertia_;
  bool band_definite_ = true;
  Eigen::MatrixXd columns_, solved_columns_, capacitance_;
  Eigen::LDLT<Eigen::MatrixXd> capacitance_factor_;
  Eigen::VectorXd capacitance_rhs_, capacitance_solution_, modal_a_, modal_b_, magnitude_;
  double time_ = 0.0, time_save_ = 0.0;
  // The sub-step being solved: its level, its fraction of the step and J's mass term.
  const Level* level_ = nullptr;
  double from_ = 0.0, to_ = 0.0, mass_term_ = 0.0;
  const Eigen::VectorXd* s_target_ = nullptr;
  Eigen::VectorXd s_, s_from_, s_to_;
  Eigen::VectorXd d_, velocity_, scratch_, d_new_, d_free_, y_free_, r_, residual_, work_,
      correction_, d_save_, correction_save_;
  Eigen::VectorXd q_, qdot_, q_free_, qdot_free_, g_from_, g_to_, rho_, q_save_, qdot_save_;
};

}  // namespace cosmems
