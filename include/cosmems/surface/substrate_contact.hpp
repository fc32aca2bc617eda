#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/surface/contact_state.hpp"
#include "cosmems/surface/impact_projection.hpp"
#include "cosmems/surface/step_start_multipliers.hpp"
#include "cosmems/surface/substrate_contact_model.hpp"

namespace cosmems {

/// The substrate as a unilateral constraint on the beam, with adhesion (stiction).
///
/// Contact: the local gap g = gap + w - separation must stay >= 0 along the beam, w the Hermite
/// cubic of u_y. It is held at points: each free node, and the quarter points of each element
/// that goes through the plane between its nodes. At a point i, g_i = gap + N_i d, the reaction
/// is p_i = max(0, lambda_i - k g_i) (augmented Lagrangian): during Newton the multipliers lambda
/// and the points holding are fixed and the force is a stiff spring k N_i^T N_i on the points
/// pressed into the substrate; once Newton converges (Settle), a point that penetrates by more
/// than the tolerance, or still pushes while clear of the plane by more than it, takes
/// lambda_i = p_i (an element's point starts to hold), and Newton runs again. A time step starts
/// with the multipliers at the reactions of the state it starts from, while that does not
/// overshoot (StepStartMultipliers). An element's
/// point is let go once it lifts clear of the plane: one kept on an element lying flat would sit on
/// the kink of max(0, .) and only slow Newton. With k = 1e4 times the beam's nodal stiffness each
/// update cuts the penetration about 1e4-fold, so a converged state meets the tolerance at every
/// point after an update or two, and the penalty's error is not left in the answer: a beam pressed
/// between two nodes of a coarse mesh stops where it is pressed, not where its nodes are. Between
/// the points the cubic may still dip a little further (at most (h/4)^2/8 of its curvature;
/// Penetration() measures the deepest place). With a surface pressure p(d) the separation must keep
/// its stiffness b |p'| below what holds the beam between the points, or the step matrix turns
/// indefinite: the Casimir pressure at 2 nm does not (10 um elements), at 20 nm it does. The gap
/// pressures stop growing at the contact plane (GapSpan::separation).
///
/// Stiction: a node pressed onto the substrate at a converged state sticks, and its constraint
/// becomes bilateral (the reaction may pull). Adhesion is released by Griffith's energy balance:
/// a stuck node at the edge of a stuck zone peels off when the energy its release would free,
/// (1/2) p^2 c (p its reaction, c the compliance of its u_y with the other constraints held;
/// virtual crack closure), exceeds Gamma times the adhered area it frees (the width times the
/// elements between it and its stuck neighbours). A node with no stuck neighbour away from a free
/// end holds no area and comes off as soon as it is pulled; so the release of one of a pair of
/// stuck nodes frees both, and its energy is that of both reactions, (1/2) p^T C p over the pair's
/// 2 x 2 compliance (without this a bridge stayed stuck on its middle two nodes at any length). For
/// a beam lying on the substrate this is the energy-release-rate balance G = M^2 / (2 E I b) =
/// Gamma at the edge of contact, which gives the S-shaped stuck cantilever's free span (Mastrangelo
/// & Hsu). At a free end (a cantilever's tip, its rotation free) a stuck node may hold alone: the
/// beam then touches by its tip, with no moment there (the arc shape), and the crack front is the
/// tip itself. Its energy release rate is the compliance method's, G = (p^2 / 2b) dc/ds with s the
/// span to the contact point; reciprocity gives dc/ds = 2 theta, theta the slope at the node under
/// a unit force there, so G = p^2 theta / b (3 E t^3 g^2 / (8 L^4) for the cantilever: the
/// arc-shaped detachment length of de Boer & Michalske). The tip lets go when G exceeds Gamma. The
/// compliance is the linear beam's (K with the contact springs), so in dynamics the criterion is
/// the quasi-static one. One node peels per Settle, the one furthest past the balance, and Newton
/// re-converges before the next.
///
/// Adhesion acts at the nodes; the points between them only stop the beam, in the elements no
/// stuck node holds.
///
/// Impacts are inelastic (ImpactProjection): at the end of each time step the velocity and the
/// acceleration of the points touching the substrate and moving into it (of every stuck node) are
/// removed by the projection that is orthogonal in the mass metric. Without it the
/// average-acceleration rule sends the nodes back off the substrate with more energy than they came
/// with: the force that stopped a node within one step stays in the step's end acceleration and
/// pushes the node off again over the next step (the reference cantilever thrown at 1 m/s gained 14
/// % and 27 % over its first two impacts; removing the velocity alone still left 8 %).
///
/// What never changes while the beam runs (the points, their shapes, the gap, the penalty, the mass
/// factor) is a SubstrateContactModel, which several contacts may share; what a run changes (the
/// multipliers, the stuck flags, the states and events, the compliance's workspace) is this
/// object's own. Evaluate(), Settle() and ProjectMotion() allocate nothing. The beam model must
/// outlive the force.
template <int Dim>
class SubstrateContact final : public NonlinearForce {
 public:
  /// A contact with a model of its own.
  SubstrateContact(const BeamModel<Dim>& model, const ContactOptions& options)
      : SubstrateContact(std::make_shared<const SubstrateContactModel<Dim>>(model, options)) {}

  /// A contact on a shared model: its state (multipliers, stuck flags, events) is its own.
  explicit SubstrateContact(std::shared_ptr<const SubstrateContactModel<Dim>> model)
      : model_(std::move(model)),
        points_(model_->points().data()),
        point_count_(model_->points().size()),
        node_count_(model_->node_count()),
        gap_(model_->gap()),
        tolerance_(model_->tolerance()),
        penalty_(model_->penalty()),
        reach_(model_->reach()),
        // A node is free when g + separation >= proximity, and touches when g <= tolerance.
        free_margin_(std::max(tolerance_, model_->proximity() - model_->options().separation /
                                                                    model_->units().length)) {
    const std::size_t m = point_count_;
    lambda_.assign(m, 0.0);
    committed_lambda_.assign(m, 0.0);
    stuck_.assign(m, 0);
    committed_stuck_.assign(m, 0);
    placed_.assign(m, 1);  // the nodes' points always; the elements' when they penetrate
    std::fill(placed_.begin() + static_cast<std::ptrdiff_t>(node_count_), placed_.end(), 0);
    committed_placed_ = placed_;
    node_state_.assign(node_count_, ContactState::kFree);
    const SymmetricBandMatrix& stiffness = model_->stiffness();
    springs_ = stiffness;
    unit_ = Eigen::VectorXd::Zero(stiffness.size());
    compliance_.Compute(springs_);  // sizes the factor's buffers, so that Settle() allocates none
    active_.assign(m, 0);
  }

  /// The constant part, to share with another contact.
  const std::shared_ptr<const SubstrateContactModel<Dim>>& model() const { return model_; }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (std::size_t k = 0; k < point_count_; ++k) {
      if (!Holds(k)) continue;
      const Point& point = points_[k];
      const double g = Gap(point, d);
      if (!std::isfinite(g)) return false;
      const double p = Reaction(k, g);
      if (!stuck_[k] && p <= 0.0) continue;
      for (int a = 0; a < 4; ++a) {
        if (point.dof[a] < 0) continue;
        force[point.dof[a]] -= p * point.shape[a];
        if (!tangent.band_wanted()) continue;
        for (int b = a; b < 4; ++b) {
          if (point.dof[b] >= 0) {
            tangent.band().Add(point.dof[a], point.dof[b],
                               penalty_ * point.shape[a] * point.shape[b]);
          }
        }
      }
    }
    return true;
  }

  // Idle: no stuck node, and every point (placed or not) clear of the plane by more than the
  // tolerance and not pushed (its multiplier below k g). Evaluate() then adds nothing, Settle()
  // places and updates nothing, ProjectMotion() holds nothing; Commit() still counts the states.
  // A contact holding nothing is idle wherever one pass over d proves every point clear.
  bool Idle(const Eigen::VectorXd& d) const override {
    if (quiet_ && ClearBy(tolerance_, d)) return true;
    for (std::size_t k = 0; k < point_count_; ++k) {
      const double g = Gap(points_[k], d);
      if (!(g > tolerance_) || stuck_[k] || lambda_[k] > penalty_ * g) return false;
    }
    return true;
  }

  bool Settle(const Eigen::VectorXd& d) override {
    bool settled = true;
    for (std::size_t k = 0; k < point_count_; ++k) {  // the multipliers' update
      const double g = Gap(points_[k], d);
      if (-g > tolerance_) {  // an element's point that went through starts to hold
        placed_[k] = 1;
        quiet_ = false;
      }
      if (!Holds(k)) continue;
      // Through the plane, or (unilateral) still pushing while clear of it by more than the
      // tolerance: a multiplier from a deeper iterate must not hold the beam up off the plane.
      const bool clear_but_pushing = !stuck_[k] && g > tolerance_ && Reaction(k, g) > 0.0;
      const double violation = stuck_[k] ? std::abs(g) : -g;
      if (violation > tolerance_ || clear_but_pushing) {
        lambda_[k] = Reaction(k, g);
        starts_.UpdatedInside(k, committed_lambda_[k]);
        quiet_ = false;
        settled = false;
      }
    }
    if (!settled || !model_->options().stiction) return settled;
    for (std::size_t k = 0; k < node_count_; ++k) {  // pressed nodes stick: same equilibrium
      if (Reaction(k, Gap(points_[k], d)) > 0.0) {
        stuck_[k] = 1;
        quiet_ = false;
      }
    }
    return !Peel(d);
  }

  void Commit(const Eigen::VectorXd& d) override {
    // Free and holding nothing, and d provably clear of the plane and of the proximity warning
    // at every point: the states, the events and the committed copies stay as they are.
    if (quiet_ && state_ == ContactState::kFree && ClearBy(free_margin_, d)) {
      starts_.Forget();
      return;
    }
    ContactState beam = ContactState::kFree;
    bool quiet = true;
    for (std::size_t k = node_count_; k < point_count_; ++k) {
      if (Holds(k) && Touching(k, Gap(points_[k], d))) {
        quiet = false;
        beam = ContactState::kContact;
      } else {  // lifted clear or adhered: let go, not to sit on the plane's kink unneeded
        placed_[k] = 0;
        lambda_[k] = 0.0;
      }
    }
    for (std::size_t k = 0; k < node_count_; ++k) {
      const double g = Gap(points_[k], d);
      quiet = quiet && !stuck_[k] && lambda_[k] == 0.0;
      ContactState& s = node_state_[k];
      if (stuck_[k]) {
        s = ContactState::kStuck;
      } else if (Touching(k, g)) {
        s = ContactState::kContact;
      } else {
        s = g + model_->options().separation / model_->units().length < model_->proximity()
                ? ContactState::kNear
                : ContactState::kFree;
      }
      beam = std::max(beam, s);
    }
    const ContactState before = state_;
    if (before < ContactState::kNear && beam >= ContactState::kNear) ++events_.proximity_warnings;
    if (before < ContactState::kContact && beam >= ContactState::kContact) ++events_.contacts;
    if (before != ContactState::kStuck && beam == ContactState::kStuck) ++events_.stuck;
    if (before == ContactState::kStuck && beam != ContactState::kStuck) ++events_.releases;
    state_ = beam;
    committed_lambda_ = lambda_;  // equal sizes: copies without allocating
    committed_stuck_ = stuck_;
    committed_placed_ = placed_;
    quiet_ = committed_quiet_ = quiet;
    for (std::size_t k = 0; k < point_count_; ++k) {
      starts_.Record(k, Holds(k) ? Reaction(k, Gap(points_[k], d)) : lambda_[k]);
    }
    starts_.Recorded(beam == ContactState::kFree);
  }

  void Revert() override {
    lambda_ = committed_lambda_;
    stuck_ = committed_stuck_;
    placed_ = committed_placed_;
    quiet_ = committed_quiet_;
  }

  void StartStep() override {
    if (starts_.Apply(lambda_)) quiet_ = false;
  }

  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    int count = 0;
    for (std::size_t k = 0; k < point_count_; ++k) {
      if (!Holds(k)) continue;
      if (stuck_[k] || (Touching(k, Gap(points_[k], d)) && Along(points_[k], v) < 0.0)) {
        active_[count++] = static_cast<int>(k);
      }
    }
    projection_.Project(
        model_->mass_factor(), active_, count,
        [&](int k, Eigen::Ref<Eigen::VectorXd> column) {
          const Point& point = points_[k];
          for (int b = 0; b < 4; ++b) {
            if (point.dof[b] >= 0) column[point.dof[b]] = point.shape[b];
          }
        },
        [&](int k, const Eigen::Ref<const Eigen::VectorXd>& x) { return Along(points_[k], x); }, v,
        a);
  }

  /// The paper's "Reset Failure": every node free and unstuck, the multipliers cleared (events
  /// are kept). The caller puts the beam back to its undeformed state, which this force does not
  /// hold (restart the integrator from rest).
  void Reset() {
    std::fill(lambda_.begin(), lambda_.end(), 0.0);
    std::fill(stuck_.begin(), stuck_.end(), 0);
    std::fill(node_state_.begin(), node_state_.end(), ContactState::kFree);
    std::fill(placed_.begin() + static_cast<std::ptrdiff_t>(node_count_), placed_.end(), 0);
    committed_placed_ = placed_;
    committed_lambda_ = lambda_;
    committed_stuck_ = stuck_;
    starts_.Forget();
    state_ = ContactState::kFree;
    quiet_ = committed_quiet_ = true;
  }

  /// Every free node stuck to the substrate, as after the beam was pressed down all along (the
  /// start of a release analysis): solve, and the adhesion peels what it cannot hold.
  void StickAll() {
    std::fill(stuck_.begin(), stuck_.begin() + static_cast<std::ptrdiff_t>(node_count_), 1);
    committed_stuck_ = stuck_;
    quiet_ = committed_quiet_ = node_count_ == 0;
    starts_.Forget();
  }

  /// The beam pressed down all along (SubstrateContactModel::PressedDisplacement).
  Eigen::VectorXd PressedDisplacement() const { return model_->PressedDisplacement(); }

  /// The largest penetration of the contact plane at d [m] (SubstrateContactModel::Penetration).
  double Penetration(const Eigen::VectorXd& d) const { return model_->Penetration(d); }

  /// The energy release rate [J/m^2] at stuck node k (an index as NodeState's) in the state d
  /// (reduced, internal units): the rate Settle() weighs against the work of adhesion at the edge
  /// of a stuck zone, or at a free end held alone (the tip of an arc-shaped cantilever). NaN
  /// where no crack front is (k not stuck, or inside a stuck zone); +inf at a node held alone
  /// away from a free end. Allocates nothing.
  double EnergyReleaseRate(int k, const Eigen::VectorXd& d) {
    const std::size_t node = Checked(k);
    if (!stuck_[node]) return std::numeric_limits<double>::quiet_NaN();
    bool factored = false;
    return ReleaseRate(node, d, factored);
  }

  /// The state of the last committed step.
  ContactSummary Summary() const {
    ContactSummary out;
    out.state = state_;
    double first = -1.0;
    for (std::size_t k = 0; k < node_count_; ++k) {
      if (node_state_[k] < ContactState::kContact) continue;
      if (first < 0.0) first = points_[k].x;
      if (k > 0 && Adjacent(k - 1, k) && node_state_[k - 1] >= ContactState::kContact) {
        out.contact_length_m += (points_[k].x - points_[k - 1].x) * model_->units().length;
      }
    }
    out.detached_length_m = (first < 0.0 ? model_->length() : first) * model_->units().length;
    if (out.Stuck()) out.shape = out.contact_length_m > 0.0 ? StuckShape::kS : StuckShape::kArc;
    return out;
  }
  const ContactEvents& events() const { return events_; }
  /// The number of nodes that can touch (the free ones), and the state of each at the last
  /// committed step, from the first support on.
  int NodeCount() const { return static_cast<int>(node_count_); }
  ContactState NodeState(int k) const { return node_state_[Checked(k)]; }
  double NodeX(int k) const { return points_[Checked(k)].x * model_->units().length; }  ///< m
  /// The penetration accepted [m], for tests and reports.
  double tolerance() const { return tolerance_ * model_->units().length; }

 private:
  // Whether point k holds: a node's always; an element's once placed, unless adhesion holds the
  // element at a node (a stuck node holds it both ways, and points between two stuck nodes would
  // hold the cubic at five places with four unknowns, whose multipliers never settle).
  bool Holds(std::size_t k) const {
    if (k < node_count_) return true;
    if (!placed_[k]) return false;
    for (int end : points_[k].ends) {
      if (end >= 0 && stuck_[static_cast<std::size_t>(end)]) return false;
    }
    return true;
  }

  double Reaction(std::size_t k, double g) const {
    const double p = lambda_[k] - penalty_ * g;
    return stuck_[k] ? p : std::max(p, 0.0);
  }

  // Pressed onto the substrate, or lying on it within the tolerance.
  bool Touching(std::size_t k, double g) const { return Reaction(k, g) > 0.0 || g <= tolerance_; }

  // Releases the pulled stuck node whose energy release rate exceeds Gamma the most; returns
  // whether one was released.
  bool Peel(const Eigen::VectorXd& d) {
    bool factored = false;
    std::size_t chosen = node_count_;
    double worst = model_->options().adhesion_energy;  // G of the chosen node [J/m^2]
    for (std::size_t k = 0; k < node_count_; ++k) {
      if (!stuck_[k] || Reaction(k, Gap(points_[k], d)) >= 0.0) continue;  // pressed: no peel
      const double rate = ReleaseRate(k, d, factored);
      if (rate > worst) {  // false for NaN: no crack front there
        worst = rate;
        chosen = k;
      }
    }
    if (chosen == node_count_) return false;
    stuck_[chosen] = 0;
    lambda_[chosen] = 0.0;
    return true;
  }

  // G at stuck node k [J/m^2]: the virtual crack closure over the adhered length its release
  // frees, or at a lone free end the compliance method's p^2 theta / b; +inf at a lone node
  // elsewhere (it holds no area), NaN inside a stuck zone (no crack front) or when the compliance
  // cannot be factored. `factored` says whether the compliance is factored for d.
  double ReleaseRate(std::size_t k, const Eigen::VectorXd& d, bool& factored) {
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    const bool left = k > 0 && Adjacent(k - 1, k) && stuck_[k - 1];
    const bool right = k + 1 < node_count_ && Adjacent(k, k + 1) && stuck_[k + 1];
    if (left && right) return kNone;
    double freed = 0.0;  // the adhered length the release frees (internal)
    if (left) freed += points_[k].x - points_[k - 1].x;
    if (right) freed += points_[k + 1].x - points_[k].x;
    const Point& point = points_[k];
    if (freed == 0.0 && point.slope < 0) return std::numeric_limits<double>::infinity();
    if (!factored && !FactorCompliance(d)) return kNone;
    factored = true;
    const double p = Reaction(k, Gap(point, d));
    const double per_length =
        model_->units().force / model_->units().length;  // internal force / length to N/m
    if (freed == 0.0) {  // a free end held alone: +inf if nothing but its own spring held it
      const NodeCompliance c = Compliance(k);
      if (!std::isfinite(c.deflection)) return std::numeric_limits<double>::infinity();
      return p * p * std::abs(c.slope) / point.width * per_length;
    }
    // A zone of two nodes away from a free end: the partner left alone holds no area and comes
    // off at once, so the release frees both, (1/2) p^T C p with C their 2 x 2 compliance.
    const std::size_t j = left ? k - 1 : k + 1;
    const bool partner_held = left ? j > 0 && Adjacent(j - 1, j) && stuck_[j - 1]
                                   : j + 1 < node_count_ && Adjacent(j, j + 1) && stuck_[j + 1];
    double energy = 0.0;
    if (!partner_held && points_[j].slope < 0) {
      energy = PairEnergy(k, j, p, Reaction(j, Gap(points_[j], d)));
    } else {
      energy = 0.5 * p * p * Compliance(k).deflection;
    }
    return energy / (point.width * freed) * per_length;
  }

  // Factors K plus the springs of the active constraints; false if it is not definite.
  bool FactorCompliance(const Eigen::VectorXd& d) {
    springs_.mutable_data() = model_->stiffness().data();
    for (std::size_t k = 0; k < point_count_; ++k) {
      if (!Holds(k) || (!stuck_[k] && Reaction(k, Gap(points_[k], d)) <= 0.0)) continue;
      const Point& point = points_[k];
      for (int a = 0; a < 4; ++a) {
        for (int b = a; b < 4; ++b) {
          if (point.dof[a] >= 0 && point.dof[b] >= 0) {
            springs_.Add(point.dof[a], point.dof[b], penalty_ * point.shape[a] * point.shape[b]);
          }
        }
      }
    }
    return compliance_.Compute(springs_).info() == Status::kOk;
  }

  // Node k's u_y and theta_z under a unit force on its u_y, with its own spring removed, from the
  // factor with it: Sherman-Morrison, A0^-1 e = A^-1 e / (1 - k e^T A^-1 e). With the penalty 1e4
  // times the nodal stiffness the subtraction loses about four of sixteen digits.
  struct NodeCompliance {
    double deflection = 0.0;  ///< c = e^T A0^-1 e (+inf when the spring held the node alone)
    double slope = 0.0;       ///< theta_z (0 unless the node is a free end)
  };
  NodeCompliance Compliance(std::size_t k) {
    const Point& point = points_[k];
    const Eigen::VectorXd& response = UnitResponse(point.dof[0]);
    const double c = response[point.dof[0]];
    const double rest = 1.0 - penalty_ * c;
    if (!(rest > 0.0)) return {std::numeric_limits<double>::infinity(), 0.0};
    return {c / rest, point.slope >= 0 ? response[point.slope] / rest : 0.0};
  }

  // The displacement under a unit force on dof w, with every active spring (the factor's).
  const Eigen::VectorXd& UnitResponse(int w) {
    unit_.setZero();
    unit_[w] = 1.0;
    compliance_.SolveInPlace(unit_);
    return unit_;
  }

  // The energy freed by releasing nodes a and b together under their reactions pa and pb,
  // (1/2) p^T C p, C their compliance with both springs removed: from S, the block of the factor's
  // inverse with them, C = S (I - k S)^-1 (Woodbury); +inf when the springs held the pair alone.
  double PairEnergy(std::size_t a, std::size_t b, double pa, double pb) {
    const int wa = points_[a].dof[0], wb = points_[b].dof[0];
    const double saa = UnitResponse(wa)[wa], sab = unit_[wb];
    const double sbb = UnitResponse(wb)[wb];
    // (I - k S)^-1 = adj / det, and C = S (I - k S)^-1.
    const double m11 = 1.0 - penalty_ * saa, m12 = -penalty_ * sab, m22 = 1.0 - penalty_ * sbb;
    const double det = m11 * m22 - m12 * m12;
    if (!(det > 0.0) || !(m11 > 0.0)) return std::numeric_limits<double>::infinity();
    const double caa = (saa * m22 - sab * m12) / det, cab = (sab * m11 - saa * m12) / det;
    const double cbb = (sbb * m11 - sab * m12) / det;
    return 0.5 * (caa * pa * pa + 2.0 * cab * pa * pb + cbb * pb * pb);
  }

  using Point = typename SubstrateContactModel<Dim>::Point;

  double Gap(const Point& point, const Eigen::VectorXd& d) const { return gap_ + Along(point, d); }

  // Whether every point is clear of the plane by more than `margin` at d, proven by one pass over
  // d (SubstrateContactModel::reach()); false when unproven (or d is not finite).
  bool ClearBy(double margin, const Eigen::VectorXd& d) const {
    return reach_ * d.cwiseAbs().template maxCoeff<Eigen::PropagateNaN>() < gap_ - margin;
  }
  std::size_t Checked(int k) const { return model_->Checked(k); }
  bool Adjacent(std::size_t a, std::size_t b) const { return model_->Adjacent(a, b); }
  static double Along(const Point& point, const Eigen::Ref<const Eigen::VectorXd>& x) {
    return SubstrateContactModel<Dim>::Along(point, x);
  }

  std::shared_ptr<const SubstrateContactModel<Dim>> model_;
  // The model's points and the constants the loops read, held here: one load each rather than two
  // through the shared pointer (the release measured 6 % slower without).
  const Point* points_;
  std::size_t point_count_;
  std::size_t node_count_;                    ///< the nodes' points, first in points_
  double gap_, tolerance_, penalty_, reach_;  ///< internal units
  double free_margin_;  ///< the clearance every point needs for the contact to be free
  std::vector<double> lambda_, committed_lambda_;
  std::vector<char> stuck_, committed_stuck_;
  std::vector<char> placed_, committed_placed_;  ///< whether each point holds (nodes: always)
  /// True only while the multipliers are zero, no node is stuck and no element's point placed,
  /// as at the last Commit() (which the committed copies then equal): the contact holds nothing.
  bool quiet_ = true, committed_quiet_ = true;
  std::vector<ContactState> node_state_;
  ContactState state_ = ContactState::kFree;
  ContactEvents events_;
  SymmetricBandMatrix springs_;
  BandCholesky compliance_;
  Eigen::VectorXd unit_;
  std::vector<int> active_;  ///< the points the projection holds
  ImpactProjection projection_{model_->stiffness().size(),
                               static_cast<Eigen::Index>(model_->points().size())};
  StepStartMultipliers starts_{model_->points().size()};
};

}  // namespace cosmems
