// A declared contact the beam is far from costs the linear step: while the contact is idle at a
// step's start and at the linear step's end, the Newmark family takes that step (one solve with
// the linear structure's factor) instead of Newton. Against Newton on every step (the same
// contact with its Idle() hidden), through approach, impacts and rebounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "cosmems/beam/load_vector.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

// The contact as it was before idle steps: never idle, so every step takes Newton.
class NeverIdle final : public NonlinearForce {
 public:
  explicit NeverIdle(NonlinearForce& force) : force_(force) {}
  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& r, ForceTangent& t) override {
    return force_.Evaluate(d, r, t);
  }
  bool Settle(const Eigen::VectorXd& d) override { return force_.Settle(d); }
  void Commit(const Eigen::VectorXd& d) override { force_.Commit(d); }
  void Revert() override { force_.Revert(); }
  void StartStep() override { force_.StartStep(); }
  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    force_.ProjectMotion(d, v, a);
  }

 private:
  NonlinearForce& force_;
};

// The 20-element reference cantilever thrown at the substrate (2 um below) at 1.5 m/s by every
// free node, 5 ns steps for 6000 steps (two periods): it flies clear, hits, rebounds and hits
// again. Until the first contact the idle run is Newton's to round-off: the linear integrator
// solves the same generalised-alpha equations for the acceleration instead of the displacement
// (3e-14 of the largest displacement measured over 190 steps; 1e-12 allowed). Contact then
// decides by thresholds (a point placed, a multiplier updated), so a difference in the last bits
// may take another branch and grow: Newton's own history, its initial velocity nudged by 1, 2 or
// 4 ulp either way, departs by 8.6e-8 to 1.3e-3 (of 0.04, internal units) over the run, depending
// on the nudge. The idle run stays within a hundredth of the largest (8.8e-7 measured), and takes
// most steps (5873 of 6000) without Newton.
TEST(IdleContactTest, IdleStepsFollowNewtonsHistoryThroughImpacts) {
  const BeamModel<2> model = test::PlanarCantilever(test::kReferenceLength, 20);
  ContactOptions options;
  options.gap = test::kReferenceGap;
  SubstrateContact<2> idle_contact(model, options), newton_contact(model, options);
  NeverIdle never_idle(newton_contact);
  const UnitSystem& u = model.units();
  const int n = model.FreeDofCount();
  Eigen::VectorXd v0 = Eigen::VectorXd::Zero(n);
  for (int node = 1; node <= 20; ++node) {
    v0[model.dofs().Reduced(node, NodalDof::kUy)] = -1.5 / (u.length / u.time);
  }
  const auto parameters = GeneralizedAlphaParameters::FromSpectralRadius(0.6);
  const double dt = 5e-9 / u.time;
  NonlinearNewmarkIntegrator idle(model.Mass(0), model.Stiffness(), {}, idle_contact, parameters,
                                  dt);
  NonlinearNewmarkIntegrator newton(model.Mass(0), model.Stiffness(), {}, never_idle, parameters,
                                    dt);
  // Newton's runs from the nudged velocities.
  struct Nudged {
    Nudged(const BeamModel<2>& model, const ContactOptions& options,
           const GeneralizedAlphaParameters& parameters, double dt)
        : contact(model, options),
          never_idle(contact),
          run(model.Mass(0), model.Stiffness(), {}, never_idle, parameters, dt) {}
    SubstrateContact<2> contact;
    NeverIdle never_idle;
    NonlinearNewmarkIntegrator run;
  };
  std::vector<std::unique_ptr<Nudged>> nudged;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  ASSERT_EQ(idle.Initialize(zero, v0, zero), Status::kOk);
  ASSERT_EQ(newton.Initialize(zero, v0, zero), Status::kOk);
  for (const double ulps : {1.0, -1.0, 2.0, -2.0, 4.0, -4.0}) {
    nudged.push_back(std::make_unique<Nudged>(model, options, parameters, dt));
    ASSERT_EQ(nudged.back()->run.Initialize(zero, v0 * (1.0 + ulps * 0x1p-52), zero), Status::kOk);
  }
  double nudge = 0.0, before_contact = 0.0;
  int idle_steps = 0, newton_steps = 0;
  double worst = 0.0, largest = 0.0;
  for (int step = 0; step < 6000; ++step) {
    ASSERT_EQ(idle.Step(zero), Status::kOk) << step;
    ASSERT_EQ(newton.Step(zero), Status::kOk) << step;
    for (const std::unique_ptr<Nudged>& other : nudged) {
      ASSERT_EQ(other->run.Step(zero), Status::kOk) << step;
      nudge = std::max(nudge,
                       (other->run.displacement() - newton.displacement()).cwiseAbs().maxCoeff());
    }
    (idle.last_stats().evaluations == 0 ? idle_steps : newton_steps) += 1;
    const double diff = (idle.displacement() - newton.displacement()).cwiseAbs().maxCoeff();
    worst = std::max(worst, diff);
    if (newton_contact.events().contacts == 0) before_contact = std::max(before_contact, diff);
    largest = std::max(largest, newton.displacement().cwiseAbs().maxCoeff());
  }
  EXPECT_GT(idle_steps, 1000);
  EXPECT_GT(newton_steps, 100);
  EXPECT_GT(idle_contact.events().contacts, 1);  // it hit, came off and hit again
  EXPECT_EQ(idle_contact.events().contacts, newton_contact.events().contacts);
  EXPECT_EQ(idle_contact.events().proximity_warnings, newton_contact.events().proximity_warnings);
  EXPECT_LE(before_contact, 1e-12 * largest);
  EXPECT_LE(worst, 1e-2 * nudge) << idle_steps << " idle steps";
}

// Idle() and Commit() prove a far beam clear of the plane from one pass over d (the points'
// largest reach) and visit the points only when that bound cannot: against every point's gap
// computed here, on the cantilever's static shape scaled from rest through the plane and back.
// Idle: every point clear by more than the tolerance. Commit: each node free, near (within the
// proximity warning's distance) or touching, the beam the worst of its nodes, and the events at
// the beam's transitions.
TEST(IdleContactTest, IdleAndCommitAgreeWithEveryPointsGap) {
  const BeamModel<2> model = test::PlanarCantilever(test::kReferenceLength, 20);
  ContactOptions options;
  options.gap = test::kReferenceGap;
  SubstrateContact<2> contact(model, options);
  const SubstrateContactModel<2>& shared = *contact.model();
  LoadCase loads;
  loads.points.push_back(
      {test::kReferenceLength, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  const Eigen::VectorXd shape = BandCholesky(model.Stiffness()).Solve(AssembleLoads(model, loads));
  const int tip = model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy);
  const double closing = shared.gap() / -shape[tip];  // the scale that brings the tip down to g = 0
  auto gap = [&](std::size_t k, const Eigen::VectorXd& d) {
    const auto& point = shared.points()[k];
    double g = shared.gap();
    for (int a = 0; a < 4; ++a) {
      if (point.dof[a] >= 0) g += point.shape[a] * d[point.dof[a]];
    }
    return g;
  };
  const double separation = options.separation / model.units().length;
  ContactState beam_before = ContactState::kFree;
  int warnings = 0, contacts = 0, idle = 0, busy = 0;
  for (int i = 0; i <= 400; ++i) {
    const double scale = closing * 1.05 * (i <= 200 ? i : 400 - i) / 200.0;
    const Eigen::VectorXd d = scale * shape;
    bool clear = true;
    for (std::size_t k = 0; k < shared.points().size(); ++k) {
      clear = clear && gap(k, d) > shared.tolerance();
    }
    ASSERT_EQ(contact.Idle(d), clear) << "scale " << scale / closing;
    (clear ? idle : busy) += 1;
    contact.Commit(d);
    ContactState beam = ContactState::kFree;
    for (int k = 0; k < contact.NodeCount(); ++k) {
      const double g = gap(static_cast<std::size_t>(k), d);
      const ContactState expected = g <= shared.tolerance()               ? ContactState::kContact
                                    : g + separation < shared.proximity() ? ContactState::kNear
                                                                          : ContactState::kFree;
      ASSERT_EQ(contact.NodeState(k), expected) << "node " << k << ", scale " << scale / closing;
      beam = std::max(beam, expected);
    }
    if (beam_before < ContactState::kNear && beam >= ContactState::kNear) ++warnings;
    if (beam_before < ContactState::kContact && beam >= ContactState::kContact) ++contacts;
    beam_before = beam;
  }
  EXPECT_GT(idle, 100);  // both sides of the sweep are visited
  EXPECT_GT(busy, 10);
  EXPECT_EQ(contacts, 1);
  EXPECT_EQ(contact.events().contacts, contacts);
  EXPECT_EQ(contact.events().proximity_warnings, warnings);
}

}  // namespace
}  // namespace cosmems
