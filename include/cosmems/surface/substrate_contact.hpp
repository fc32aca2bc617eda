#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/surface/contact_state.hpp"

namespace cosmems {

struct ContactOptions {
  double gap = 0.0;  ///< m, from the beam's undeformed lower face to the substrate
  /// m: how close the faces come in contact (asperities, a native oxide). Keeps the surface
  /// pressures, which grow without bound as the gap closes, finite on a beam lying down.
  double separation = 0.0;
  bool stiction = false;
  double adhesion_energy = 0.0;  ///< work of adhesion Gamma [J/m^2], with stiction
  double proximity = 0.0;        ///< m: a local gap below this is "near"; 0: a tenth of the gap
  double tolerance = 0.0;        ///< m: the penetration accepted; 0: 1e-4 of the gap
  /// The augmented-Lagrangian penalty per node, relative to the beam's largest u_y stiffness.
  double penalty = 1e4;
};

/// The substrate as a unilateral constraint on the beam's nodes, with adhesion (stiction).
///
/// Contact: the local gap g_i = gap + w_i - separation at each free node must stay >= 0. The
/// reaction is p_i = max(0, lambda_i - k g_i) (augmented Lagrangian): during Newton the
/// multipliers lambda are fixed and the force is a stiff spring on the nodes pressed into the
/// substrate; once Newton converges (Settle) a node that penetrates by more than the tolerance
/// takes lambda_i = p_i and Newton runs again. With k = 1e4 times the beam's nodal stiffness each
/// update cuts the penetration about 1e4-fold, so a converged state meets the tolerance after one
/// update or none, and the penalty's error is not left in the answer. The constraint acts at the
/// nodes: between two nodes lying on the substrate the beam's cubic may dip below it by a small
/// fraction of the nodal rotation times the element length. With a surface pressure p(d) the
/// separation must keep its stiffness b |p'| below the elements' bending stiffness between the
/// nodes, or nothing holds the beam there: the Casimir pressure at 2 nm does not (10 um
/// elements), at 20 nm it does; the solvers then report a matrix that is not positive definite.
///
/// Stiction: a node pressed onto the substrate at a converged state sticks, and its constraint
/// becomes bilateral (the reaction may pull). Adhesion is released by Griffith's energy balance:
/// a stuck node at the edge of a stuck zone peels off when the energy its release would free,
/// (1/2) p^2 c (p its reaction, c the compliance of its u_y with the other constraints held;
/// virtual crack closure), exceeds Gamma times the adhered area it frees (the width times the
/// elements between it and its stuck neighbours). A node with no stuck neighbour holds no area
/// and comes off as soon as it is pulled. For a beam lying on the substrate this is the
/// energy-release-rate balance G = M^2 / (2 E I b) = Gamma at the edge of contact, which gives the
/// S-shaped stuck cantilever's free span (Mastrangelo & Hsu). The compliance is the linear beam's
/// (K with the contact springs), so in dynamics the criterion is the quasi-static one. One node
/// peels per Settle, the one furthest past the balance, and Newton re-converges before the next.
///
/// Impacts are inelastic at the nodes: at the end of each time step the velocity and the
/// acceleration of the nodes touching the substrate and moving into it (of every stuck node) are
/// removed by the projection that is orthogonal in the mass metric, x -= M^-1 C^T (C M^-1 C^T)^-1
/// C x, which can only lower the kinetic energy. Without it the average-acceleration rule sends
/// the nodes back off the substrate with more energy than they came with: the force that stopped
/// a node within one step stays in the step's end acceleration and pushes the node off again over
/// the next step (the reference cantilever thrown at 1 m/s gained 14 % and 27 % over its first
/// two impacts; removing the velocity alone still left 8 %).
///
/// Evaluate(), Settle() and ProjectMotion() allocate nothing. The beam model must outlive the
/// force.
template <int Dim>
class SubstrateContact final : public NonlinearForce {
 public:
  SubstrateContact(const BeamModel<Dim>& model, const ContactOptions& options)
      : stiffness_(model.Stiffness()), units_(model.units()), options_(options) {
    RequirePositive("gap", options.gap);
    RequireWithin("separation", options.separation, 0.0, 0.5 * options.gap);
    if (options.stiction) RequirePositive("adhesion_energy", options.adhesion_energy);
    constexpr double kLargest = std::numeric_limits<double>::max();
    RequireWithin("proximity", options.proximity, 0.0, kLargest);
    RequireWithin("tolerance", options.tolerance, 0.0, kLargest);
    RequireWithin("penalty", options.penalty, 10.0, 1e8);
    const UnitSystem& u = model.units();
    gap_ = (options.gap - options.separation) / u.length;
    tolerance_ = (options.tolerance > 0.0 ? options.tolerance : 1e-4 * options.gap) / u.length;
    proximity_ = (options.proximity > 0.0 ? options.proximity : 0.1 * options.gap) / u.length;
    double largest = 0.0;
    for (int node = 0; node < model.NodeCount(); ++node) {
      const int w = model.dofs().Reduced(node, NodalDof::kUy);
      if (w < 0) continue;  // a support never reaches the substrate
      const int e = std::min(node, model.ElementCount() - 1);
      nodes_.push_back(
          {w, node, model.NodeX()[node], model.description().elements[e].section.width / u.length});
      largest = std::max(largest, stiffness_(w, w));
    }
    penalty_ = options.penalty * largest;
    length_ = model.NodeX().back();
    const std::size_t m = nodes_.size();
    lambda_.assign(m, 0.0);
    committed_lambda_.assign(m, 0.0);
    stuck_.assign(m, 0);
    committed_stuck_.assign(m, 0);
    node_state_.assign(m, ContactState::kFree);
    springs_ = stiffness_;
    unit_ = Eigen::VectorXd::Zero(stiffness_.size());
    compliance_.Compute(springs_);  // sizes the factor's buffers, so that Settle() allocates none
    mass_factor_.Compute(model.Mass(0));
    columns_ = Eigen::MatrixXd::Zero(stiffness_.size(), static_cast<Eigen::Index>(m));
    schur_ = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
    multipliers_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m));
    active_.assign(m, 0);
    held_set_.assign(m, 0);
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const double g = gap_ + d[nodes_[k].w];
      if (!std::isfinite(g)) return false;
      const double p = Reaction(k, g);
      if (!stuck_[k] && p <= 0.0) continue;
      force[nodes_[k].w] -= p;
      tangent.band().Add(nodes_[k].w, nodes_[k].w, penalty_);
    }
    return true;
  }

  bool Settle(const Eigen::VectorXd& d) override {
    bool settled = true;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {  // the multipliers' update
      const double g = gap_ + d[nodes_[k].w];
      const double violation = stuck_[k] ? std::abs(g) : -g;
      if (violation > tolerance_) {
        lambda_[k] = Reaction(k, g);
        settled = false;
      }
    }
    if (!settled || !options_.stiction) return settled;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {  // pressed nodes stick: same equilibrium
      if (Reaction(k, gap_ + d[nodes_[k].w]) > 0.0) stuck_[k] = 1;
    }
    return !Peel(d);
  }

  void Commit(const Eigen::VectorXd& d) override {
    ContactState beam = ContactState::kFree;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const double g = gap_ + d[nodes_[k].w];
      ContactState& s = node_state_[k];
      if (stuck_[k]) {
        s = ContactState::kStuck;
      } else if (Touching(k, g)) {
        s = ContactState::kContact;
      } else {
        s = g + options_.separation / units_.length < proximity_ ? ContactState::kNear
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
  }

  void Revert() override {
    lambda_ = committed_lambda_;
    stuck_ = committed_stuck_;
  }

  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    int count = 0;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      const int w = nodes_[k].w;
      if (stuck_[k] || (Touching(k, gap_ + d[w]) && v[w] < 0.0)) active_[count++] = w;
    }
    if (count == 0 || mass_factor_.info() != Status::kOk) return;
    // M^-1 C^T and the factor of C M^-1 C^T depend on the held nodes alone: a stuck zone held
    // step after step reuses them.
    if (count != held_ ||
        !std::equal(active_.begin(), active_.begin() + count, held_set_.begin())) {
      held_ = 0;
      for (int j = 0; j < count; ++j) {
        auto column = columns_.col(j);
        column.setZero();
        column[active_[j]] = 1.0;
        mass_factor_.SolveInPlace(column);
        for (int i = 0; i < count; ++i) schur_(i, j) = column[active_[i]];
      }
      Eigen::Ref<Eigen::MatrixXd> schur = schur_.topLeftCorner(count, count);
      Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> llt(schur);  // in place: allocates nothing
      if (llt.info() != Eigen::Success) return;
      std::copy(active_.begin(), active_.begin() + count, held_set_.begin());
      held_ = count;
    }
    const auto lower = schur_.topLeftCorner(count, count).triangularView<Eigen::Lower>();
    for (Eigen::VectorXd* x : {&v, &a}) {
      auto m = multipliers_.head(count);
      for (int j = 0; j < count; ++j) m[j] = (*x)[active_[j]];
      lower.solveInPlace(m);
      lower.adjoint().solveInPlace(m);
      x->noalias() -= columns_.leftCols(count) * m;
    }
  }

  /// The paper's "Reset Failure": every node free and unstuck, the multipliers cleared (events
  /// are kept). The caller puts the beam back to its undeformed state, which this force does not
  /// hold (restart the integrator from rest).
  void Reset() {
    std::fill(lambda_.begin(), lambda_.end(), 0.0);
    std::fill(stuck_.begin(), stuck_.end(), 0);
    std::fill(node_state_.begin(), node_state_.end(), ContactState::kFree);
    committed_lambda_ = lambda_;
    committed_stuck_ = stuck_;
    state_ = ContactState::kFree;
  }

  /// Every free node stuck to the substrate, as after the beam was pressed down all along (the
  /// start of a release analysis): solve, and the adhesion peels what it cannot hold.
  void StickAll() {
    std::fill(stuck_.begin(), stuck_.end(), 1);
    committed_stuck_ = stuck_;
  }

  /// The displacement with every free node on the contact plane and flat (internal units): the
  /// beam pressed down all along, a start for the solvers. The nodes sit the tolerance deep, so
  /// that the contact holds them from the first iteration on (a node exactly on the plane is not
  /// pressed, and a surface pressure alone would make the first Newton matrix indefinite).
  Eigen::VectorXd PressedDisplacement() const {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(stiffness_.size());
    for (const Node& node : nodes_) d[node.w] = -gap_ - tolerance_;
    return d;
  }

  /// The largest penetration of the contact plane at the nodes of d [m] (0 when none).
  double Penetration(const Eigen::VectorXd& d) const {
    double deepest = 0.0;
    for (const Node& node : nodes_) deepest = std::max(deepest, -(gap_ + d[node.w]));
    return deepest * units_.length;
  }

  /// The state of the last committed step.
  ContactSummary Summary() const {
    ContactSummary out;
    out.state = state_;
    double first = -1.0;
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      if (node_state_[k] < ContactState::kContact) continue;
      if (first < 0.0) first = nodes_[k].x;
      if (k > 0 && Adjacent(k - 1, k) && node_state_[k - 1] >= ContactState::kContact) {
        out.contact_length_m += (nodes_[k].x - nodes_[k - 1].x) * units_.length;
      }
    }
    out.detached_length_m = (first < 0.0 ? length_ : first) * units_.length;
    return out;
  }
  const ContactEvents& events() const { return events_; }
  /// The number of nodes that can touch (the free ones), and the state of each at the last
  /// committed step, from the first support on.
  int NodeCount() const { return static_cast<int>(nodes_.size()); }
  ContactState NodeState(int k) const { return node_state_.at(k); }
  double NodeX(int k) const { return nodes_.at(k).x * units_.length; }  ///< m
  /// The penetration accepted [m], for tests and reports.
  double tolerance() const { return tolerance_ * units_.length; }

 private:
  struct Node {
    int w;         ///< reduced index of u_y
    int node;      ///< node number along the beam
    double x;      ///< internal units
    double width;  ///< internal units
  };

  double Reaction(std::size_t k, double g) const {
    const double p = lambda_[k] - penalty_ * g;
    return stuck_[k] ? p : std::max(p, 0.0);
  }

  // Pressed onto the substrate, or lying on it within the tolerance.
  bool Touching(std::size_t k, double g) const { return Reaction(k, g) > 0.0 || g <= tolerance_; }

  bool Adjacent(std::size_t a, std::size_t b) const { return nodes_[b].node == nodes_[a].node + 1; }

  // Releases the pulled stuck node whose release frees the most energy per area beyond Gamma;
  // returns whether one was released.
  bool Peel(const Eigen::VectorXd& d) {
    bool factored = false;
    std::size_t chosen = nodes_.size();
    double worst = 1.0;  // G / Gamma of the chosen node
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      if (!stuck_[k]) continue;
      const double p = Reaction(k, gap_ + d[nodes_[k].w]);
      if (p >= 0.0) continue;  // pressed, or not pulled: nothing to peel
      const bool left = k > 0 && Adjacent(k - 1, k) && stuck_[k - 1];
      const bool right = k + 1 < nodes_.size() && Adjacent(k, k + 1) && stuck_[k + 1];
      if (left && right) continue;  // inside a stuck zone: peeling starts at its edges
      double freed = 0.0;           // the adhered length the release frees (internal)
      if (left) freed += nodes_[k].x - nodes_[k - 1].x;
      if (right) freed += nodes_[k + 1].x - nodes_[k].x;
      double ratio = std::numeric_limits<double>::infinity();
      if (freed > 0.0) {
        if (!factored && !FactorCompliance(d)) return false;
        factored = true;
        const double energy = 0.5 * p * p * Compliance(k) * units_.force * units_.length;
        const double area = nodes_[k].width * freed * units_.length * units_.length;
        ratio = energy / (options_.adhesion_energy * area);
      }
      if (ratio > worst) {
        worst = ratio;
        chosen = k;
      }
    }
    if (chosen == nodes_.size()) return false;
    stuck_[chosen] = 0;
    lambda_[chosen] = 0.0;
    return true;
  }

  // Factors K plus the springs of the active constraints; false if it is not definite.
  bool FactorCompliance(const Eigen::VectorXd& d) {
    springs_.mutable_data() = stiffness_.data();
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
      if (stuck_[k] || Reaction(k, gap_ + d[nodes_[k].w]) > 0.0) {
        springs_.Add(nodes_[k].w, nodes_[k].w, penalty_);
      }
    }
    return compliance_.Compute(springs_).info() == Status::kOk;
  }

  // The compliance of node k's u_y with its own spring removed, from the factor with it: Sherman-
  // Morrison on c = e^T A^-1 e. With the penalty 1e4 times the nodal stiffness the subtraction
  // loses about four of sixteen digits.
  double Compliance(std::size_t k) {
    const int w = nodes_[k].w;
    unit_.setZero();
    unit_[w] = 1.0;
    compliance_.SolveInPlace(unit_);
    const double c = unit_[w];
    const double rest = 1.0 - penalty_ * c;
    return rest > 0.0 ? c / rest : std::numeric_limits<double>::infinity();
  }

  const SymmetricBandMatrix& stiffness_;
  UnitSystem units_;
  ContactOptions options_;
  double gap_ = 0.0, tolerance_ = 0.0, proximity_ = 0.0, penalty_ = 0.0, length_ = 0.0;
  std::vector<Node> nodes_;
  std::vector<double> lambda_, committed_lambda_;
  std::vector<char> stuck_, committed_stuck_;
  std::vector<ContactState> node_state_;
  ContactState state_ = ContactState::kFree;
  ContactEvents events_;
  SymmetricBandMatrix springs_;
  BandCholesky compliance_;
  Eigen::VectorXd unit_;
  BandCholesky mass_factor_;
  Eigen::MatrixXd columns_, schur_;
  Eigen::VectorXd multipliers_;
  std::vector<int> active_;    ///< reduced indices of the nodes the projection holds
  std::vector<int> held_set_;  ///< the held nodes columns_ and schur_ were made for
  int held_ = 0;               ///< their count (0: none made)
};

}  // namespace cosmems
