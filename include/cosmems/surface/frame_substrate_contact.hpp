#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/contact_state.hpp"
#include "cosmems/surface/frame_gap_points.hpp"
#include "cosmems/surface/impact_projection.hpp"
#include "cosmems/surface/substrate_contact_model.hpp"

namespace cosmems {

/// The substrate as a unilateral constraint under any structure (a FrameModel): the beam's
/// contact law (SubstrateContact) at the points where a device's faces can touch first
/// (FrameGapLayout::kContact: each member element's nodes and quarter points on its lower face,
/// each body's four lower corners), each at its own gap to the contact plane, `gap` below the
/// structure's lowest face and `separation` above the substrate.
///
/// At a point, g = g_0 + n . d, n its motion toward +y per degree of freedom (the member's Hermite
/// cubic, or the body's u_y + theta x r), and the reaction p = max(0, lambda - k g) (augmented
/// Lagrangian): during Newton the multipliers are fixed and the points pressed into the substrate
/// are stiff springs k n n^T; once Newton converges (Settle) a point through the plane by more than
/// the tolerance, or still pushing while clear of it by more than the tolerance, takes lambda = p,
/// and Newton runs again, so a converged state meets the tolerance at every point. Each point's k
/// is `penalty` times the structure's stiffness there, 1 / (n^T K^-1 n): a device's stiffness
/// differs between its points by orders of magnitude (a plate on soft springs beside short stiff
/// connectors), and a penalty scaled to the stiffest would make the pressed plate's Newton matrix
/// too ill-conditioned to converge (measured: a serpentine's plate touching down failed with the
/// penalty 1e4 times the largest u_y stiffness, not with its own). A plate lying flat is held at
/// its four corners, one more than its three motions normal to the substrate: the multipliers share
/// its reaction among them in one of the ways that balance it.
///
/// Impacts are inelastic (ImpactProjection), as on the beam. Adhesion (stiction) is not modelled
/// here: a structure pressed onto the substrate comes off as soon as it is let go. Evaluate(),
/// Settle(), Commit() and ProjectMotion() allocate nothing; the model must outlive the force.
class FrameSubstrateContact final : public NonlinearForce {
 public:
  /// Takes the gap, separation, tolerance, proximity and penalty of `options` (the beam's
  /// meanings, with the structure's lowest face for the beam's); throws std::invalid_argument as
  /// SubstrateContactModel does, and for stiction.
  FrameSubstrateContact(const FrameModel& model, const ContactOptions& options)
      : points_(model, FrameGapOptions{options.gap, {Electrode{}}, 4, FrameGapLayout::kContact}),
        length_m_(model.units().length),
        projection_(model.FreeDofCount(), static_cast<Eigen::Index>(points_.points().size())) {
    RequireWithin("separation", options.separation, 0.0, 0.5 * options.gap);
    if (options.stiction) {
      throw std::invalid_argument("stiction: a device's contact holds no adhesion");
    }
    constexpr double kLargest = std::numeric_limits<double>::max();
    RequireWithin("proximity", options.proximity, 0.0, kLargest);
    RequireWithin("tolerance", options.tolerance, 0.0, kLargest);
    RequireWithin("penalty", options.penalty, 10.0, 1e8);
    separation_ = options.separation / length_m_;
    tolerance_ = (options.tolerance > 0.0 ? options.tolerance : 1e-4 * options.gap) / length_m_;
    proximity_ = (options.proximity > 0.0 ? options.proximity : 0.1 * options.gap) / length_m_;
    const std::size_t m = points_.points().size();
    const BandCholesky stiffness(model.Stiffness());
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(model.FreeDofCount());
    penalty_.assign(m, 0.0);
    for (std::size_t k = 0; k < m; ++k) {
      const DofWeights& point = points_.points()[k];
      if (point.count == 0) continue;  // held by anchors: it never moves
      unit.setZero();
      for (int i = 0; i < point.count; ++i) unit[point.dof[i]] = point.n[i];
      stiffness.SolveInPlace(unit);
      const double compliance = point.Dot(unit);
      if (!(compliance > 0.0)) throw std::invalid_argument("contact: the structure is not stable");
      penalty_[k] = options.penalty / compliance;
    }
    rest_.resize(m);
    nearest_ = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < m; ++k) {
      const FrameGapPoints::Point& point = points_.points()[k];
      rest_[k] = point.gap_m / length_m_ - separation_;
      nearest_ = std::min(nearest_, rest_[k]);
      double reach = 0.0;
      for (int i = 0; i < point.count; ++i) reach += std::abs(point.n[i]);
      reach_ = std::max(reach_, reach);
    }
    lambda_.assign(m, 0.0);
    committed_lambda_.assign(m, 0.0);
    active_.assign(m, 0);
    mass_factor_.Compute(model.Mass(0));
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      const double g = Gap(k, d);
      if (!std::isfinite(g)) return false;
      const double p = Reaction(k, g);
      if (p <= 0.0) continue;
      const DofWeights& point = points_.points()[k];
      for (int a = 0; a < point.count; ++a) {
        force[point.dof[a]] -= p * point.n[a];
        for (int b = 0; b < point.count; ++b) {
          if (point.dof[b] >= point.dof[a]) {
            tangent.band().Add(point.dof[a], point.dof[b], penalty_[k] * point.n[a] * point.n[b]);
          }
        }
      }
    }
    return true;
  }

  // Idle: every point clear of the plane by more than the tolerance and not pushed; proven by one
  // pass over d while no multiplier is held.
  bool Idle(const Eigen::VectorXd& d) const override {
    if (quiet_ && ClearBy(tolerance_, d)) return true;
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      const double g = Gap(k, d);
      if (!(g > tolerance_) || lambda_[k] > penalty_[k] * g) return false;
    }
    return true;
  }

  bool Settle(const Eigen::VectorXd& d) override {
    bool settled = true;
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      const double g = Gap(k, d);
      // Through the plane, or still pushing while clear of it: a multiplier from a deeper iterate
      // must not hold the structure up off the plane.
      if (-g > tolerance_ || (g > tolerance_ && Reaction(k, g) > 0.0)) {
        lambda_[k] = Reaction(k, g);
        quiet_ = false;
        settled = false;
      }
    }
    return settled;
  }

  void Commit(const Eigen::VectorXd& d) override {
    // Holding nothing and provably clear of the proximity distance: nothing to count.
    if (quiet_ && state_ == ContactState::kFree &&
        ClearBy(std::max(tolerance_, proximity_ - separation_), d)) {
      return;
    }
    ContactState state = ContactState::kFree;
    bool quiet = true;
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      const double g = Gap(k, d);
      quiet = quiet && lambda_[k] == 0.0;
      if (Touching(k, g)) {
        state = ContactState::kContact;
      } else if (g + separation_ < proximity_) {
        state = std::max(state, ContactState::kNear);
      }
    }
    const ContactState before = state_;
    if (before < ContactState::kNear && state >= ContactState::kNear) ++events_.proximity_warnings;
    if (before < ContactState::kContact && state >= ContactState::kContact) ++events_.contacts;
    state_ = state;
    committed_lambda_ = lambda_;  // equal sizes: copies without allocating
    quiet_ = committed_quiet_ = quiet;
  }

  void Revert() override {
    lambda_ = committed_lambda_;
    quiet_ = committed_quiet_;
  }

  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    int count = 0;
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      if (Touching(k, Gap(k, d)) && points_.Along(points_.points()[k], v) < 0.0) {
        active_[count++] = static_cast<int>(k);
      }
    }
    projection_.Project(
        mass_factor_, active_, count,
        [&](int k, Eigen::Ref<Eigen::VectorXd> column) {
          const DofWeights& point = points_.points()[k];
          for (int i = 0; i < point.count; ++i) column[point.dof[i]] = point.n[i];
        },
        [&](int k, const Eigen::Ref<const Eigen::VectorXd>& x) {
          const DofWeights& point = points_.points()[k];
          double sum = 0.0;
          for (int i = 0; i < point.count; ++i) sum += point.n[i] * x[point.dof[i]];
          return sum;
        },
        v, a);
  }

  /// The paper's "Reset Failure": the multipliers cleared, the state free (events are kept).
  void Reset() {
    std::fill(lambda_.begin(), lambda_.end(), 0.0);
    committed_lambda_ = lambda_;
    state_ = ContactState::kFree;
    quiet_ = committed_quiet_ = true;
  }

  /// The state of the last committed step: free, near or touching (a device's summary has no
  /// stuck shape and no lengths).
  ContactSummary Summary() const {
    ContactSummary out;
    out.state = state_;
    return out;
  }
  const ContactEvents& events() const { return events_; }

  /// The points held, their gaps at rest and motions (FrameGapPoints, kContact layout).
  const FrameGapPoints& points() const { return points_; }
  /// The local gap to the contact plane at point k for d [m] (negative: through it).
  double GapM(std::size_t k, const Eigen::VectorXd& d) const { return Gap(k, d) * length_m_; }
  /// The largest penetration of the contact plane at any point for d [m] (0 when none).
  double Penetration(const Eigen::VectorXd& d) const {
    double deepest = 0.0;
    for (std::size_t k = 0; k < rest_.size(); ++k) deepest = std::max(deepest, -Gap(k, d));
    return deepest * length_m_;
  }
  /// The penetration accepted [m].
  double tolerance() const { return tolerance_ * length_m_; }
  /// The augmented Lagrangian's penalty k at point k (internal units).
  double penalty(std::size_t k) const { return penalty_[k]; }

 private:
  double Gap(std::size_t k, const Eigen::VectorXd& d) const {
    return rest_[k] + points_.points()[k].Dot(d);
  }
  double Reaction(std::size_t k, double g) const {
    return std::max(lambda_[k] - penalty_[k] * g, 0.0);
  }
  // Pressed onto the substrate, or lying on it within the tolerance.
  bool Touching(std::size_t k, double g) const { return Reaction(k, g) > 0.0 || g <= tolerance_; }
  // Whether every point is clear of the plane by more than `margin` at d, proven by one pass over
  // d (no point moves by more than reach_ max |d_i|); false when unproven or d is not finite.
  bool ClearBy(double margin, const Eigen::VectorXd& d) const {
    return reach_ * d.cwiseAbs().template maxCoeff<Eigen::PropagateNaN>() < nearest_ - margin;
  }

  FrameGapPoints points_;
  double length_m_;
  double separation_ = 0.0, tolerance_ = 0.0, proximity_ = 0.0;  ///< internal units
  std::vector<double> penalty_;  ///< each point's k (internal units)
  double reach_ = 0.0;           ///< the largest sum of a point's |weights|
  double nearest_ = 0.0;         ///< the smallest gap at rest to the contact plane (internal)
  std::vector<double> rest_;     ///< each point's gap at rest to the contact plane (internal)
  std::vector<double> lambda_, committed_lambda_;
  bool quiet_ = true, committed_quiet_ = true;  ///< no multiplier held (as at the last Commit)
  ContactState state_ = ContactState::kFree;
  ContactEvents events_;
  std::vector<int> active_;
  BandCholesky mass_factor_;
  ImpactProjection projection_;
};

}  // namespace cosmems
