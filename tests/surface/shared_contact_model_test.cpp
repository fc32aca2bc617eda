// One SubstrateContactModel shared by two analyses running at the same time: its constant data is
// read-only, so each analysis ends exactly where it ends on a model of its own. Built also under
// ThreadSanitizer, which proves that the two threads share no written state.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <thread>
#include <utility>
#include <vector>

#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

struct Outcome {
  Status status = Status::kOk;
  Eigen::VectorXd d;
  ContactSummary summary;
  ContactEvents events;
  std::vector<ContactState> nodes;
};

// A static solve on `contact`: from lying flat with every node stuck (the release analysis), or
// from rest under the tip force `tip`.
Outcome Solve(const BeamModel<2>& model, SubstrateContact<2>& contact, bool release, double tip) {
  NonlinearStaticOptions options;
  LoadCase loads;
  if (release) {
    contact.StickAll();
    options.start = contact.PressedDisplacement();
  } else {
    loads.points.push_back(
        {test::kReferenceLength, Eigen::Vector3d(0, tip, 0), Eigen::Vector3d::Zero()});
  }
  const NonlinearStaticSolution solution = SolveNonlinearStatic(model, contact, loads, options);
  Outcome out{solution.status, solution.displacement, contact.Summary(), contact.events(), {}};
  for (int k = 0; k < contact.NodeCount(); ++k) out.nodes.push_back(contact.NodeState(k));
  return out;
}

// The reference cantilever with stiction (Gamma = 0.02 J/m^2): released from lying flat it stays
// stuck in an S (its length exceeds the 142 um free span), pressed by three times the force that
// closes the gap it rests on its tip, which the adhesion then holds. The two analyses run on two
// threads over one model and end bit for bit where each ends alone: the same arithmetic on the
// same constant data.
TEST(SharedContactModelTest, TwoAnalysesOnOneModelRunAsIfEachHadItsOwn) {
  const BeamModel<2> model = test::PlanarCantilever(test::kReferenceLength, 40);
  ContactOptions options;
  options.gap = test::kReferenceGap;
  options.stiction = true;
  options.adhesion_energy = 0.02;
  const double tip = -9.0 * test::Eiz() * test::kReferenceGap / std::pow(test::kReferenceLength, 3);

  SubstrateContact<2> own_release(model, options), own_press(model, options);
  const Outcome alone[2] = {Solve(model, own_release, true, 0.0),
                            Solve(model, own_press, false, tip)};

  const auto shared = std::make_shared<const SubstrateContactModel<2>>(model, options);
  SubstrateContact<2> a(shared), b(shared);
  EXPECT_EQ(a.model(), b.model());
  EXPECT_EQ(shared.use_count(), 3);
  Outcome together[2];
  std::thread first([&] { together[0] = Solve(model, a, true, 0.0); });
  std::thread second([&] { together[1] = Solve(model, b, false, tip); });
  first.join();
  second.join();

  for (int i = 0; i < 2; ++i) {
    const Outcome &x = alone[i], &y = together[i];
    EXPECT_EQ(x.status, Status::kOk) << i;
    EXPECT_EQ(y.status, Status::kOk) << i;
    ASSERT_EQ(x.d.size(), y.d.size()) << i;
    EXPECT_TRUE(x.d.cwiseEqual(y.d).all()) << i;
    EXPECT_EQ(x.summary.state, y.summary.state) << i;
    EXPECT_EQ(x.summary.shape, y.summary.shape) << i;
    EXPECT_EQ(x.summary.detached_length_m, y.summary.detached_length_m) << i;
    EXPECT_EQ(x.summary.contact_length_m, y.summary.contact_length_m) << i;
    EXPECT_EQ(x.events.contacts, y.events.contacts) << i;
    EXPECT_EQ(x.events.stuck, y.events.stuck) << i;
    EXPECT_EQ(x.events.releases, y.events.releases) << i;
    EXPECT_EQ(x.nodes, y.nodes) << i;
  }
  // The two ended in different states, so neither could have borrowed the other's.
  EXPECT_EQ(together[0].summary.shape, StuckShape::kS);
  EXPECT_EQ(together[1].summary.shape, StuckShape::kArc);
}

}  // namespace
}  // namespace cosmems
