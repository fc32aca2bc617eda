#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/surface/contact_state.hpp"
#include "cosmems/surface/frame_adhesion_sites.hpp"
#include "cosmems/surface/frame_contact_points.hpp"
#include "cosmems/surface/impact_projection.hpp"
#include "cosmems/surface/step_start_multipliers.hpp"
#include "cosmems/surface/substrate_contact_model.hpp"

namespace cosmems {

/// The substrate as a unilateral constraint under any structure (a FrameModel): the beam's
/// contact law (SubstrateContact) at the points where a device's faces can touch first
/// (FrameContactPoints: each member element's nodes and quarter points on its lower face,
/// each body's four lower corners), each at its own gap to the contact plane, `gap` below the
/// structure's lowest face and `separation` above the substrate.
///
/// At a point, g = g_0 + n . d, n its motion toward +y per degree of freedom (the member's Hermite
/// cubic, or the body's u_y + theta x r), and the reaction p = max(0, lambda - k g) (augmented
/// Lagrangian): during Newton the multipliers are fixed and the points pressed into the substrate
/// are stiff springs k n n^T; once Newton converges (Settle) a point through the plane by more than
/// the tolerance, or still pushing while clear of it by more than the tolerance, takes lambda = p,
/// and Newton runs again, so a converged state meets the tolerance at every point. A time step
/// starts with the multipliers at the reactions of the state it starts from, while that does not
/// overshoot (StepStartMultipliers). Each point's k
/// is `penalty` times the structure's stiffness there, 1 / (n^T K^-1 n): a device's stiffness
/// differs between its points by orders of magnitude (a plate on soft springs beside short stiff
/// connectors), and a penalty scaled to the stiffest would make the pressed plate's Newton matrix
/// too ill-conditioned to converge (measured: a serpentine's plate touching down failed with the
/// penalty 1e4 times the largest u_y stiffness, not with its own). A stuck member node's k
/// is `penalty` times its stiffness with every other motion held, n^T K n (the beam's nodal
/// stiffness): a member lying stuck is held by its neighbours, far stiffer than free (a
/// cantilever's tip 1e6 times at 100 elements), and a penalty below that cuts the penetration too
/// little per multiplier update (the released cantilever ran out of updates). That held stiffness
/// grows as the cube of the element count, so it is capped at kHeldStiffnessCap times the free
/// one: uncapped, the shuttle of a 1000-element folded flexure (125 a beam) stuck under the probe
/// made Newton's matrix too ill-conditioned to converge (penalties 6.5e12 against 9.4e7 on K's
/// diagonal), while the cap leaves the 100-element member's release the beam's. Everywhere else the
/// free structure's: held, a plate's corner would take the stiffness of the short connectors
/// attached to the plate, and the stuck serpentine plate's Newton, as ill-conditioned, failed
/// every haptic tick; on every point, the contact's penalty failed 46 % of the ticks of that plate
/// pressed onto the substrate without adhesion. A plate lying flat is held at
/// its four corners, one more than its three motions normal to the substrate: the multipliers share
/// its reaction among them in one of the ways that balance it.
///
/// Stiction (FrameAdhesionSites): at a converged state a member's node pressed onto the substrate
/// sticks, as on the beam, and so does a body lying flat on it (its four corners touching, pressed
/// as a whole); a stuck point's constraint is bilateral. Griffith's balance releases them, one per
/// Settle (the one furthest past it), as on the beam: a member's stuck node at the edge of a stuck
/// run peels when the energy its release frees, (1/2) p^T C p over it (and over a neighbour left
/// holding nothing), exceeds Gamma times the width times the length it frees; a free end stuck
/// alone by the compliance method's G = p^2 theta / b (the arc-shaped cantilever); a body, pulled
/// as a whole, when (1/2) p^T C p over its four corners exceeds Gamma times its face: the plate's
/// stiction criterion, the suspension's stored energy against the adhesion of the face (for a
/// plate on springs k pressed down by g, (1/2) k g^2 against Gamma A). C is the compliance of the
/// released points with their springs removed (Woodbury, from the factor with them); four corners
/// move in three ways, and the formula needs C only through p^T C p, which stays defined.
///
/// Impacts are inelastic (ImpactProjection), as on the beam: stuck points are held too. A member
/// element's points give it their reactions as its share (LocalForce), so a device's statics on
/// the substrate recover its reactions and stresses with them. Evaluate(), Settle(), Commit() and
/// ProjectMotion() allocate nothing; the model must outlive the force.
class FrameSubstrateContact final : public FrameElementForce {
 public:
  /// Takes the gap, separation, tolerance, proximity, penalty and stiction of `options` (the
  /// beam's meanings, with the structure's lowest face for the beam's); throws
  /// std::invalid_argument as SubstrateContactModel does.
  FrameSubstrateContact(const FrameModel& model, const ContactOptions& options)
      : points_(model, options.gap),
        sites_(model, points_),
        model_(model),
        length_m_(model.units().length),
        projection_(model.FreeDofCount(), static_cast<Eigen::Index>(points_.points().size())),
        starts_(points_.points().size()) {
    RequireWithin("separation", options.separation, 0.0, 0.5 * options.gap);
    if (options.stiction) RequirePositive("adhesion_energy", options.adhesion_energy);
    stiction_ = options.stiction;
    adhesion_energy_ = options.adhesion_energy;
    bodies_first_ = static_cast<std::size_t>(points_.first(model.ElementCount()));
    constexpr double kLargest = std::numeric_limits<double>::max();
    RequireWithin("proximity", options.proximity, 0.0, kLargest);
    RequireWithin("tolerance", options.tolerance, 0.0, kLargest);
    RequireWithin("penalty", options.penalty, 10.0, 1e8);
    separation_ = options.separation / length_m_;
    tolerance_ = (options.tolerance > 0.0 ? options.tolerance : 1e-4 * options.gap) / length_m_;
    proximity_ = (options.proximity > 0.0 ? options.proximity : 0.1 * options.gap) / length_m_;
    const std::size_t m = points_.points().size();
    const SymmetricBandMatrix& stiffness = model.Stiffness();
    const BandCholesky factor(stiffness);
    if (factor.info() != Status::kOk) {
      throw std::invalid_argument("contact: the structure is not stable");
    }
    // A point's weights lie within the band (its spring k n n^T is added to it), so K^-1's band
    // gives every point's compliance n^T K^-1 n.
    const SymmetricBandMatrix inverse = factor.InverseWithinBand();
    free_penalty_.assign(m, 0.0);
    stuck_penalty_.assign(m, 0.0);
    for (std::size_t k = 0; k < m; ++k) {
      const DofWeights& point = points_.points()[k];
      if (point.count == 0) continue;  // held by anchors: it never moves
      const double compliance = point.QuadraticForm(inverse);
      if (!(compliance > 0.0)) throw std::invalid_argument("contact: the structure is not stable");
      free_penalty_[k] = options.penalty / compliance;
      stuck_penalty_[k] = free_penalty_[k];
      if (sites_.SiteOf(k) < 0) continue;  // a plate's corner: stuck, the plate is as free
      const double held = point.QuadraticForm(stiffness);  // n^T K n
      stuck_penalty_[k] = options.penalty * std::min(held, kHeldStiffnessCap / compliance);
    }
    rest_.resize(m);
    nearest_ = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < m; ++k) {
      const FrameContactPoints::Point& point = points_.points()[k];
      rest_[k] = point.gap_m / length_m_ - separation_;
      nearest_ = std::min(nearest_, rest_[k]);
      double reach = 0.0;
      for (int i = 0; i < point.count; ++i) reach += std::abs(point.n[i]);
      reach_ = std::max(reach_, reach);
    }
    gaps_ = rest_;  // the gaps at rest
    gaps_state_.setZero(model.FreeDofCount());
    lambda_.assign(m, 0.0);
    committed_lambda_.assign(m, 0.0);
    stuck_.assign(m, 0);
    committed_stuck_.assign(m, 0);
    touching_.assign(m, 0);
    active_.assign(m, 0);
    mass_factor_.Compute(model.Mass(0));
    if (stiction_) {  // the compliance's buffers, sized now so that Settle() allocates none
      springs_ = model.Stiffness();
      compliance_.Compute(springs_);
      for (Eigen::VectorXd& response : responses_) response.setZero(model.FreeDofCount());
    }
  }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    const std::vector<double>& gaps = Gaps(d);
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      if (!Holds(k)) continue;
      const double g = gaps[k];
      if (!std::isfinite(g)) return false;
      const double p = Reaction(k, g);
      if (!stuck_[k] && p <= 0.0) continue;  // a stuck point holds both ways, at any p
      const DofWeights& point = points_.points()[k];
      for (int a = 0; a < point.count; ++a) {
        force[point.dof[a]] -= p * point.n[a];
        if (!tangent.band_wanted()) continue;
        for (int b = 0; b < point.count; ++b) {
          if (point.dof[b] >= point.dof[a]) {
            tangent.band().Add(point.dof[a], point.dof[b], Penalty(k) * point.n[a] * point.n[b]);
          }
        }
      }
    }
    return true;
  }

  /// The reactions of element e's points, on its lower face, in its axes (internal units).
  FrameModel::ElementVector LocalForce(const Eigen::VectorXd& d, int e) const override {
    FrameModel::ElementVector out = FrameModel::ElementVector::Zero();
    for (int k = points_.first(e); k < points_.first(e + 1); ++k) {
      const auto point = static_cast<std::size_t>(k);
      if (!Holds(point)) continue;
      const double p = Reaction(point, Gap(point, d));  // a free point's is never negative
      out -= p * points_.points()[point].local;
    }
    return out;
  }

  // Idle: every point clear of the plane by more than the tolerance and not pushed; proven by one
  // pass over d while no multiplier is held.
  bool Idle(const Eigen::VectorXd& d) const override {
    if (quiet_ && ClearBy(tolerance_, d)) return true;
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      const double g = Gap(k, d);
      if (!(g > tolerance_) || stuck_[k] || lambda_[k] > free_penalty_[k] * g) return false;
    }
    return true;
  }

  bool Settle(const Eigen::VectorXd& d) override {
    const std::vector<double>& gaps = Gaps(d);
    bool settled = true;
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      if (!Holds(k)) continue;
      const double g = gaps[k];
      // Through the plane (or off it, when stuck), or still pushing while clear of it: a
      // multiplier from a deeper iterate must not hold the structure up off the plane.
      const double violation = stuck_[k] ? std::abs(g) : -g;
      if (violation > tolerance_ || (!stuck_[k] && g > tolerance_ && Reaction(k, g) > 0.0)) {
        lambda_[k] = Reaction(k, g);
        starts_.UpdatedInside(k, committed_lambda_[k]);
        quiet_ = false;
        settled = false;
      }
    }
    if (!settled || !stiction_) return settled;
    Stick(gaps);
    return !Peel(gaps);
  }

  void Commit(const Eigen::VectorXd& d) override {
    // Holding nothing and provably clear of the proximity distance: nothing to count.
    if (quiet_ && state_ == ContactState::kFree &&
        ClearBy(std::max(tolerance_, proximity_ - separation_), d)) {
      starts_.Forget();
      return;
    }
    ContactState state = ContactState::kFree;
    bool quiet = true;
    const std::vector<double>& gaps = Gaps(d);
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      // Each point's flags read once into locals: the store to touching_, a char, may alias
      // anything, and would have every later read of a member come back from memory (1.96
      // against 1.40 us a Commit of the stuck resonator).
      const double g = gaps[k];
      const bool stuck = stuck_[k] != 0, holds = Holds(k);
      quiet = quiet && lambda_[k] == 0.0 && !stuck;
      starts_.Record(k, holds ? Reaction(k, g) : lambda_[k]);
      const bool touching = stuck || (holds && Touching(k, g));
      touching_[k] = touching;
      if (stuck) {
        state = ContactState::kStuck;
      } else if (touching) {
        state = std::max(state, ContactState::kContact);
      } else if (g + separation_ < proximity_) {
        state = std::max(state, ContactState::kNear);
      }
    }
    const ContactState before = state_;
    if (before < ContactState::kNear && state >= ContactState::kNear) ++events_.proximity_warnings;
    if (before < ContactState::kContact && state >= ContactState::kContact) ++events_.contacts;
    if (before != ContactState::kStuck && state == ContactState::kStuck) ++events_.stuck;
    if (before == ContactState::kStuck && state != ContactState::kStuck) ++events_.releases;
    state_ = state;
    committed_lambda_ = lambda_;  // equal sizes: copies without allocating
    committed_stuck_ = stuck_;
    quiet_ = committed_quiet_ = quiet;
    starts_.Recorded(state == ContactState::kFree);
  }

  void Revert() override {
    lambda_ = committed_lambda_;
    stuck_ = committed_stuck_;
    quiet_ = committed_quiet_;
  }

  void StartStep() override {
    if (starts_.Apply(lambda_)) quiet_ = false;
  }

  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    int count = 0;
    const std::vector<double>& gaps = Gaps(d);
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      if (!Holds(k)) continue;
      if (stuck_[k] || (Touching(k, gaps[k]) && points_.Along(points_.points()[k], v) < 0.0)) {
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
    std::fill(stuck_.begin(), stuck_.end(), 0);
    std::fill(touching_.begin(), touching_.end(), 0);
    committed_lambda_ = lambda_;
    committed_stuck_ = stuck_;
    state_ = ContactState::kFree;
    quiet_ = committed_quiet_ = true;
    starts_.Forget();
  }

  /// Every point that can stick stuck, as after the device was pressed down all over (the start
  /// of a release analysis): solve from PressedDisplacement(), and the adhesion lets go what it
  /// cannot hold.
  void StickAll() {
    for (const FrameAdhesionSites::Site& site : sites_.sites()) Fix(site.point);
    for (const FrameAdhesionSites::Plate& plate : sites_.plates()) {
      for (int k = plate.first; k < plate.first + 4; ++k) Fix(k);
    }
    committed_stuck_ = stuck_;
    quiet_ = committed_quiet_ = false;
    starts_.Forget();
  }

  /// The device pressed down all over, every node and body that can move on the contact plane
  /// (reduced, internal units): where a release analysis starts.
  Eigen::VectorXd PressedDisplacement() const {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(model_.FreeDofCount());
    const FrameMesh& mesh = model_.mesh();
    for (const FrameAdhesionSites::Site& site : sites_.sites()) {
      const int carrier = mesh.nodes[site.node].carrier;
      const int uy = model_.CarrierDof(carrier, 1);
      if (mesh.carriers[carrier].body < 0 && uy >= 0) d[uy] = -rest_[site.point] - tolerance_;
    }
    for (std::size_t b = 0; b < sites_.plates().size(); ++b) {
      const int uy = model_.CarrierDof(mesh.body_carrier[b], 1);
      if (uy >= 0) d[uy] = -rest_[sites_.plates()[b].first] - tolerance_;
    }
    return d;
  }

  /// The state of the last committed step: free, near, touching or stuck, and when stuck its
  /// shape (along a length or a face, or by free ends alone: the arc). A one-member structure's
  /// (a beam's) has its member's lengths; a device's has none (MemberSummary has each member's).
  ContactSummary Summary() const {
    ContactSummary out;
    out.state = state_;
    if (out.Stuck()) {
      out.shape = StuckShape::kArc;
      for (std::size_t k = 0; k < rest_.size(); ++k) {
        const int site = sites_.SiteOf(k);
        if (stuck_[k] && (site < 0 || !sites_.sites()[site].free_end)) out.shape = StuckShape::kS;
      }
    }
    if (model_.description().members.size() == 1) {
      const ContactSummary member = MemberSummary(0);
      out.contact_length_m = member.contact_length_m;
      out.detached_length_m = member.detached_length_m;
    }
    return out;
  }

  /// A member's contact at the last committed step, as a beam's: its state, its length lying on
  /// the substrate (runs of touching nodes), its free span from its first node to its first
  /// touching node (its whole length when none touches) and its stuck shape.
  ContactSummary MemberSummary(int member) const {
    ContactSummary out;
    const double length = sites_.MemberLength(member);
    double first = -1.0;
    for (const FrameAdhesionSites::Site& site : sites_.sites()) {
      if (site.member != member || !touching_[site.point]) continue;
      const ContactState state = stuck_[site.point] ? ContactState::kStuck : ContactState::kContact;
      out.state = std::max(out.state, state);
      if (first < 0.0) first = site.s;
      if (site.previous >= 0 && touching_[sites_.sites()[site.previous].point]) {
        out.contact_length_m += (site.s - sites_.sites()[site.previous].s) * length_m_;
      }
    }
    out.detached_length_m = (first < 0.0 ? length : first) * length_m_;
    if (out.Stuck()) out.shape = out.contact_length_m > 0.0 ? StuckShape::kS : StuckShape::kArc;
    return out;
  }

  /// Whether body b lay stuck to the substrate at the last committed step.
  bool BodyStuck(int b) const { return stuck_[sites_.plates()[b].first] != 0; }

  /// The energy release rate [J/m^2] at the stuck member node `site` (FrameAdhesionSites) in
  /// the state d, as Settle() weighs it against the work of adhesion: NaN where no crack front is
  /// (not stuck, or inside a stuck run), +inf where the node holds no area. Allocates nothing.
  double EnergyReleaseRate(int site, const Eigen::VectorXd& d) {
    const FrameAdhesionSites::Site& s = sites_.sites().at(static_cast<std::size_t>(site));
    if (!stuck_[s.point]) return std::numeric_limits<double>::quiet_NaN();
    bool factored = false;
    return SiteReleaseRate(s, Gaps(d), factored);
  }

  /// The energy [J] the release of body b's plate would free in the state d, (1/2) p^T C p over
  /// its corners (+inf when only their springs held it), and the work of adhesion of its face [J].
  std::pair<double, double> PlateEnergies(int b, const Eigen::VectorXd& d) {
    const FrameAdhesionSites::Plate& plate = sites_.plates().at(static_cast<std::size_t>(b));
    const std::vector<double>& gaps = Gaps(d);
    if (!FactorCompliance(gaps)) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
    const double joule = model_.units().force * length_m_;
    return {PlateEnergy(plate, gaps) * joule,
            adhesion_energy_ * plate.area * length_m_ * length_m_};
  }
  const ContactEvents& events() const { return events_; }

  /// The points held, their gaps at rest and motions (FrameContactPoints).
  const FrameContactPoints& points() const { return points_; }
  /// Where adhesion can hold the points (FrameAdhesionSites).
  const FrameAdhesionSites& sites() const { return sites_; }
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
  double penalty(std::size_t k) const { return Penalty(k); }

 private:
  double Gap(std::size_t k, const Eigen::VectorXd& d) const {
    return rest_[k] + points_.points()[k].Dot(d);
  }
  // Every point's gap for d. A tick hands the same state to Settle(), ProjectMotion() and
  // Commit() in turn (and often to the Evaluate() before them): its gaps, a pass over every
  // point's weights that each of them and Settle()'s stiction passes made afresh, are formed once
  // and kept with the state they belong to, which is known by its values (the callers' vectors
  // are buffers they reuse).
  const std::vector<double>& Gaps(const Eigen::VectorXd& d) {
    const auto bytes = sizeof(double) * static_cast<std::size_t>(d.size());
    if (d.size() == gaps_state_.size() && std::memcmp(gaps_state_.data(), d.data(), bytes) == 0) {
      return gaps_;
    }
    for (std::size_t k = 0; k < rest_.size(); ++k) gaps_[k] = Gap(k, d);
    gaps_state_ = d;  // equal sizes: copies without allocating
    return gaps_;
  }
  // A point's k: a stuck one's is held by its neighbours, a free one's by the structure.
  double Penalty(std::size_t k) const { return stuck_[k] ? stuck_penalty_[k] : free_penalty_[k]; }
  double Reaction(std::size_t k, double g) const {
    const double p = lambda_[k] - Penalty(k) * g;
    return stuck_[k] ? p : std::max(p, 0.0);
  }
  // Whether point k holds: always, but for an element's inner point while adhesion holds either
  // end of its element (the stuck ends hold it both ways; an inner point besides would hold the
  // cubic at more places than it has unknowns, and its multiplier would never settle), and for a
  // member's end on a stuck body (the plate's corners hold it).
  bool Holds(std::size_t k) const {
    for (int end : sites_.HeldBy(k)) {
      if (end >= 0 && stuck_[static_cast<std::size_t>(end)]) return false;
    }
    return true;
  }
  void Fix(int k) {
    if (points_.points()[k].count > 0) stuck_[k] = 1;  // an anchored point never moves
  }

  // Pressed member nodes stick; a body sticks when it lies flat (every corner touching) and is
  // pressed as a whole.
  void Stick(const std::vector<double>& gaps) {
    for (const FrameAdhesionSites::Site& site : sites_.sites()) {
      if (Reaction(site.point, gaps[site.point]) > 0.0) Fix(site.point);
    }
    for (const FrameAdhesionSites::Plate& plate : sites_.plates()) {
      double pressed = 0.0;
      bool flat = true;
      for (int k = plate.first; k < plate.first + 4; ++k) {
        const double g = gaps[k];
        flat = flat && Touching(k, g);
        pressed += Reaction(k, g);
      }
      if (!flat || !(pressed > 0.0)) continue;
      for (int k = plate.first; k < plate.first + 4; ++k) Fix(k);
    }
  }

  // Releases the stuck node or plate whose energy release rate exceeds Gamma the most; returns
  // whether one was released.
  bool Peel(const std::vector<double>& gaps) {
    bool factored = false;
    int chosen = -1;  // a site's point, or a plate's first corner
    double worst = adhesion_energy_;
    for (const FrameAdhesionSites::Site& site : sites_.sites()) {
      const std::size_t k = site.point;
      if (!stuck_[k] || Reaction(k, gaps[k]) >= 0.0) continue;  // pressed: no peel
      const double rate = SiteReleaseRate(site, gaps, factored);
      if (rate > worst) {  // false for NaN: no crack front there
        worst = rate;
        chosen = site.point;
      }
    }
    const double per_length = model_.units().force / length_m_;  // internal force/length to N/m
    for (const FrameAdhesionSites::Plate& plate : sites_.plates()) {
      if (!stuck_[plate.first]) continue;
      double pull = 0.0;
      for (int k = plate.first; k < plate.first + 4; ++k) pull += Reaction(k, gaps[k]);
      if (!(pull < 0.0)) continue;  // pressed as a whole: no release
      if (!factored && !FactorCompliance(gaps)) continue;
      factored = true;
      const double rate = PlateEnergy(plate, gaps) / plate.area * per_length;
      if (rate > worst) {
        worst = rate;
        chosen = plate.first;
      }
    }
    if (chosen < 0) return false;
    const int plate = sites_.PlateOf(static_cast<std::size_t>(chosen), bodies_first_);
    const int last = plate >= 0 ? chosen + 4 : chosen + 1;
    for (int k = chosen; k < last; ++k) {
      stuck_[k] = 0;
      lambda_[k] = 0.0;
    }
    return true;
  }

  // G at a stuck member node [J/m^2]: the virtual crack closure over the adhered length its
  // release frees, or at a free end held alone the compliance method's p^2 theta / b; +inf at a
  // lone node elsewhere (it holds no area), NaN inside a stuck run (no crack front) or when the
  // compliance cannot be factored.
  double SiteReleaseRate(const FrameAdhesionSites::Site& site, const std::vector<double>& gaps,
                         bool& factored) {
    const std::vector<FrameAdhesionSites::Site>& all = sites_.sites();
    auto stuck = [&](int s) { return s >= 0 && stuck_[all[s].point]; };
    const bool before = stuck(site.previous), after = stuck(site.next);
    if (before && after) return std::numeric_limits<double>::quiet_NaN();
    double freed = 0.0;  // the adhered length the release frees (internal)
    if (before) freed += site.s - all[site.previous].s;
    if (after) freed += all[site.next].s - site.s;
    if (freed == 0.0 && !site.free_end) return std::numeric_limits<double>::infinity();
    if (!factored && !FactorCompliance(gaps)) return std::numeric_limits<double>::quiet_NaN();
    factored = true;
    const double per_length = model_.units().force / length_m_;
    const std::size_t k = site.point;
    const double p = Reaction(k, gaps[k]);
    const DofWeights& n = points_.points()[k];
    if (freed == 0.0) {  // a free end held alone: its slope under a unit force, its spring removed
      const double s = n.Dot(Response(0, n));
      const double rest = 1.0 - Penalty(k) * s;
      if (!(rest > 0.0)) return std::numeric_limits<double>::infinity();
      const double theta = site.slope.Dot(responses_[0]) / rest;
      return p * p * std::abs(theta) / site.width * per_length;
    }
    // A run of two nodes away from a free end: the partner left alone holds no area and comes off
    // at once, so the release frees both.
    const FrameAdhesionSites::Site& partner = all[before ? site.previous : site.next];
    const bool partner_held = before ? stuck(partner.previous) : stuck(partner.next);
    std::array<int, 2> group{site.point, partner.point};
    const int count = !partner_held && !partner.free_end ? 2 : 1;
    return GroupEnergy(group.data(), count, gaps) / (site.width * freed) * per_length;
  }

  // The energy (internal) freed by releasing the plate's four corners together.
  double PlateEnergy(const FrameAdhesionSites::Plate& plate, const std::vector<double>& gaps) {
    const std::array<int, 4> group{plate.first, plate.first + 1, plate.first + 2, plate.first + 3};
    return GroupEnergy(group.data(), 4, gaps);
  }

  // (1/2) p^T C p over the `count` points `group` under their reactions p, C their compliance
  // with their springs removed: from S = N^T A^-1 N (A the factored matrix with the springs),
  // C = S + S (K^-1 - S)^-1 S (Woodbury), K their penalties; +inf when K^-1 - S is not definite
  // (the springs held the points alone). Needs the compliance factored for the state of `gaps`.
  double GroupEnergy(const int* group, int count, const std::vector<double>& gaps) {
    using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 4, 4>;
    using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 4, 1>;
    Small s(count, count), rest(count, count);
    SmallVector p(count);
    for (int i = 0; i < count; ++i) {
      const DofWeights& n = points_.points()[group[i]];
      Response(i, n);
      p[i] = Reaction(group[i], gaps[group[i]]);
    }
    for (int i = 0; i < count; ++i) {
      for (int j = 0; j < count; ++j) s(i, j) = points_.points()[group[i]].Dot(responses_[j]);
    }
    rest = -s;
    for (int i = 0; i < count; ++i) rest(i, i) += 1.0 / Penalty(group[i]);
    const Eigen::LLT<Small> factor(rest);
    if (factor.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
    const SmallVector sp = s * p;
    return 0.5 * (p.dot(sp) + sp.dot(factor.solve(sp)));
  }

  // responses_[i] = A^-1 n for the point's weights n.
  const Eigen::VectorXd& Response(int i, const DofWeights& n) {
    Eigen::VectorXd& response = responses_[i];
    response.setZero();
    for (int a = 0; a < n.count; ++a) response[n.dof[a]] = n.n[a];
    compliance_.SolveInPlace(response);
    return response;
  }

  // Factors K plus the springs of the points holding; false if it is not definite.
  bool FactorCompliance(const std::vector<double>& gaps) {
    springs_.mutable_data() = model_.Stiffness().data();
    for (std::size_t k = 0; k < rest_.size(); ++k) {
      if (!Holds(k) || (!stuck_[k] && Reaction(k, gaps[k]) <= 0.0)) continue;
      const DofWeights& point = points_.points()[k];
      for (int a = 0; a < point.count; ++a) {
        for (int b = 0; b < point.count; ++b) {
          if (point.dof[b] >= point.dof[a]) {
            springs_.Add(point.dof[a], point.dof[b], Penalty(k) * point.n[a] * point.n[b]);
          }
        }
      }
    }
    return compliance_.Compute(springs_).info() == Status::kOk;
  }
  // Pressed onto the substrate, or lying on it within the tolerance.
  bool Touching(std::size_t k, double g) const { return Reaction(k, g) > 0.0 || g <= tolerance_; }
  // Whether every point is clear of the plane by more than `margin` at d, proven by one pass over
  // d (no point moves by more than reach_ max |d_i|); false when unproven or d is not finite.
  bool ClearBy(double margin, const Eigen::VectorXd& d) const {
    return reach_ * d.cwiseAbs().template maxCoeff<Eigen::PropagateNaN>() < nearest_ - margin;
  }

  FrameContactPoints points_;
  FrameAdhesionSites sites_;
  const FrameModel& model_;
  double length_m_;
  double separation_ = 0.0, tolerance_ = 0.0, proximity_ = 0.0;  ///< internal units
  /// A stuck node's held stiffness at most this many times its free one. Measured on the release
  /// of the 100-element cantilever member: 1e4 and above keep its detached span the beam's
  /// (142 um), 1e3 gives 140 um and 100 gives 154 um.
  static constexpr double kHeldStiffnessCap = 1e4;
  std::vector<double> free_penalty_, stuck_penalty_;  ///< each point's k (internal units)
  double reach_ = 0.0;                                ///< the largest sum of a point's |weights|
  double nearest_ = 0.0;      ///< the smallest gap at rest to the contact plane (internal)
  std::vector<double> rest_;  ///< each point's gap at rest to the contact plane (internal)
  std::vector<double> lambda_, committed_lambda_;
  std::vector<char> stuck_, committed_stuck_;
  std::vector<char> touching_;  ///< whether each point touched at the last Commit
  bool stiction_ = false;
  double adhesion_energy_ = 0.0;  ///< Gamma [J/m^2]
  std::size_t bodies_first_ = 0;  ///< the first body corner among the points
  /// no multiplier held and nothing stuck (as at the last Commit)
  bool quiet_ = true, committed_quiet_ = true;
  ContactState state_ = ContactState::kFree;
  ContactEvents events_;
  std::vector<int> active_;
  BandCholesky mass_factor_;
  ImpactProjection projection_;
  SymmetricBandMatrix springs_;  ///< K with the springs of the points holding (stiction)
  BandCholesky compliance_;
  std::array<Eigen::VectorXd, 4> responses_;  ///< A^-1 n for up to four released points
  StepStartMultipliers starts_;
  std::vector<double> gaps_;    ///< every point's gap at gaps_state_ (Gaps)
  Eigen::VectorXd gaps_state_;  ///< the state gaps_ belongs to
};

}  // namespace cosmems
