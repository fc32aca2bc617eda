// The substrate under any structure (FrameSubstrateContact): its force and tangent against
// differences of the penalty's energy, a plate pressed onto the substrate by the probe held on
// the contact plane within the tolerance with the probe's force the coupling's closed form, and
// the impact's projection removing the held points' approach without adding kinetic energy.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/haptics/haptic_structure.hpp"
#include "cosmems/surface/frame_substrate_contact.hpp"
#include "force_differences.hpp"
#include "structure/test_frames.hpp"
#include "surface/plate_on_four_beams.hpp"

namespace cosmems {
namespace {

constexpr double kGap = 1e-6;  // m, below the plate's and the beams' lower faces

ContactOptions Substrate() {
  ContactOptions options;
  options.gap = kGap;
  return options;
}

// The plate down by `sink` and tilted about z, the beams following: some corners through the
// contact plane, none within the differences' step of it (the law's kink).
Eigen::VectorXd PressedTilted(const FrameModel& model, double sink, double tilt) {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const int plate = model.mesh().body_carrier[0];
  d[model.CarrierDof(plate, 1)] = -sink / model.units().length;
  d[model.CarrierDof(plate, 5)] = tilt;
  return d;
}

TEST(FrameSubstrateContactTest, ForceAndTangentAreThePenaltysEnergyDifferences) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  FrameSubstrateContact contact(model, Substrate());
  // Down 1.02 um and turned 0.01 rad: corners at +-50 um are 0.48 um apart in height.
  const Eigen::VectorXd d = PressedTilted(model, 1.02e-6, 0.01);
  ASSERT_GT(contact.Penetration(d), 0.0);
  const double length = model.units().length;
  for (std::size_t i = 0; i < contact.points().points().size(); ++i) {
    ASSERT_GT(std::abs(contact.GapM(i, d)), 1e-9) << "point " << i << " on the kink";
  }
  // With no multiplier, the energy is sum (k_i/2) min(g_i, 0)^2 in internal units.
  auto energy = [&](const Eigen::VectorXd& x) {
    double e = 0.0;
    for (std::size_t i = 0; i < contact.points().points().size(); ++i) {
      const double g = std::min(contact.GapM(i, x) / length, 0.0);
      e += 0.5 * contact.penalty(i) * g * g;
    }
    return e;
  };
  // Differences of step 1e-6 (internal units: 1e-6 of a micrometre) against a penetration of
  // 0.26 um: the kinks stay 3 orders of magnitude away; the quadratic energy's central
  // differences are exact but for round-off.
  test::ExpectForceAndTangentMatchDifferences(contact, d, model.Stiffness().bandwidth(), energy,
                                              1e-6, 1e-7);
}

// The contact keeps every point's gap for the last state it saw (a tick's Settle, ProjectMotion
// and Commit share one) and knows a state by its values: a caller's vector changed in place
// between two calls is a new state, whose force and settling are a fresh contact's there, to the
// bit (the same arithmetic).
TEST(FrameSubstrateContactTest, AVectorChangedInPlaceIsANewState) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  const int n = model.FreeDofCount(), bandwidth = model.Stiffness().bandwidth();
  auto force = [&](FrameSubstrateContact& contact, const Eigen::VectorXd& d) {
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    ForceTangent tangent(n, bandwidth);
    EXPECT_TRUE(contact.Evaluate(d, f, tangent));
    return f;
  };
  const Eigen::VectorXd deep = PressedTilted(model, 1.02e-6, 0.01);
  const Eigen::VectorXd shallow = PressedTilted(model, 1.01e-6, -0.005);
  FrameSubstrateContact contact(model, Substrate()), fresh(model, Substrate());
  Eigen::VectorXd state = deep;
  const Eigen::VectorXd at_deep = force(contact, state);
  const double* buffer = state.data();
  state = shallow;
  ASSERT_EQ(state.data(), buffer);  // the same buffer, new values
  const Eigen::VectorXd at_shallow = force(contact, state);
  EXPECT_FALSE(at_shallow.isApprox(at_deep));
  EXPECT_TRUE(at_shallow == force(fresh, shallow));
  EXPECT_EQ(contact.Settle(state), fresh.Settle(shallow));
  EXPECT_TRUE(force(contact, state) == force(fresh, shallow));
}

// The probe presses the plate's centre 3 um down over a substrate 1 um below it: the plate comes
// to rest on the contact plane, within the tolerance (1e-4 of the gap), and the probe's force is
// the coupling's compression alone, k_c (face - g - (y_p - r)), the plate no longer moving.
TEST(FrameSubstrateContactTest, APlatePressedOntoTheSubstrateRestsOnIt) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  FrameSubstrateContact contact(model, Substrate());
  const double radius = 2e-6, k_c = 5.0 * plate.k, face = 1e-6;
  HapticStructure structure(model, ProbeOptions{radius, k_c}, &contact, &contact);
  const double probe_y = face + radius - 3e-6;
  for (int tick = 0; tick < 20; ++tick) {
    ASSERT_EQ(structure.Advance({0.0, probe_y, 0.0}, 1e-3 * tick), Status::kOk) << tick;
  }
  const Eigen::VectorXd& d = structure.displacement();
  EXPECT_LE(contact.Penetration(d), contact.tolerance());
  const double u = d[model.CarrierDof(model.mesh().body_carrier[0], 1)] * model.units().length;
  EXPECT_NEAR(u, -kGap, contact.tolerance());
  const double expected = k_c * (face - kGap - (probe_y - radius));
  // The plate's place is known to the tolerance, 1e-10 m of the coupling's 2 um compression.
  EXPECT_NEAR(structure.local_model().force_n, expected, 1e-4 * expected);
  HapticFrame frame = structure.MakeFrame();
  EXPECT_EQ(frame.contact.state, ContactState::kContact);
  EXPECT_EQ(frame.events.contacts, 1);
  EXPECT_EQ(frame.events.proximity_warnings, 1);
  // Lifted away, the plate springs back off the substrate, the state free.
  for (int tick = 0; tick < 20; ++tick) {
    ASSERT_EQ(structure.Advance({0.0, face + radius + 1e-6, 0.0}, 1e-3 * (20 + tick)), Status::kOk);
  }
  structure.Fill(frame);
  EXPECT_EQ(frame.contact.state, ContactState::kFree);
  EXPECT_EQ(structure.local_model().force_n, 0.0);
}

// The plate on the substrate, moving into it and sideways and turning: the projection stops every
// touching point's approach, keeps what moves away, and never raises the kinetic energy.
TEST(FrameSubstrateContactTest, TheImpactStopsTheApproachWithoutAddingEnergy) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  FrameSubstrateContact contact(model, Substrate());
  const Eigen::VectorXd d = PressedTilted(model, kGap, 0.0);  // lying flat on the plane
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  Eigen::VectorXd v(model.FreeDofCount()), a(model.FreeDofCount());
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    v[i] = normal(random);
    a[i] = normal(random);
  }
  v[model.CarrierDof(model.mesh().body_carrier[0], 1)] = -10.0;  // down, hard
  const Eigen::MatrixXd mass = model.Mass(0).ToDense();
  const double before = v.dot(mass * v);
  Eigen::VectorXd approach_before(contact.points().points().size());
  for (std::size_t i = 0; i < contact.points().points().size(); ++i) {
    approach_before[static_cast<Eigen::Index>(i)] = contact.points().points()[i].Dot(v);
  }
  contact.ProjectMotion(d, v, a);
  EXPECT_LT(v.dot(mass * v), before);
  int held = 0;
  for (std::size_t i = 0; i < contact.points().points().size(); ++i) {
    if (contact.GapM(i, d) > contact.tolerance()) continue;
    if (approach_before[static_cast<Eigen::Index>(i)] < 0.0) {
      ++held;
      EXPECT_NEAR(contact.points().points()[i].Dot(v), 0.0,
                  1e-9 * std::abs(approach_before[static_cast<Eigen::Index>(i)]));
    }
  }
  EXPECT_GE(held, 4);  // the plate's corners at least
}

// A member's points give their elements their reactions (LocalForce): carried to the global
// axes and scattered to each element's unknowns, the shares are the contact's force, point by
// point the same products summed in another order (round-off apart). A bridge of four elements
// pressed 1.5 gaps down at its middle, its inner points through the plane.
TEST(FrameSubstrateContactTest, TheElementsSharesAddUpToTheContactsForce) {
  StructureDescription s;
  const int left = test::AddNode(s, "left", Eigen::Vector3d::Zero(), Support::kClamped);
  const int right = test::AddNode(s, "right", Eigen::Vector3d(200e-6, 0.0, 0.0), Support::kClamped);
  test::AddBeam(s, left, right, 4);
  const FrameModel model(s);
  FrameSubstrateContact contact(model, Substrate());
  // The bridge's first mode's shape, scaled: its middle 1.5 gaps down.
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (int n = 0; n < static_cast<int>(model.mesh().nodes.size()); ++n) {
    const double x = model.mesh().nodes[n].position.x() / 200e-6;
    const double w = 1.5 * kGap * std::pow(std::sin(M_PI * x), 2) / model.units().length;
    const int uy = model.CarrierDof(model.mesh().nodes[n].carrier, 1);
    if (uy >= 0) d[uy] = -w;
  }
  ASSERT_GT(contact.Penetration(d), 0.4 * kGap);
  Eigen::VectorXd force = Eigen::VectorXd::Zero(model.FreeDofCount());
  ForceTangent tangent(model.FreeDofCount(), model.Stiffness().bandwidth());
  ASSERT_TRUE(contact.Evaluate(d, force, tangent));
  Eigen::VectorXd shares = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (int e = 0; e < model.ElementCount(); ++e) {
    const FrameModel::ElementVector global =
        model.ElementTransform(e).transpose() * contact.LocalForce(d, e);
    for (int a = 0; a < 12; ++a) {
      if (model.ElementDofs(e)[a] >= 0) shares[model.ElementDofs(e)[a]] += global[a];
    }
  }
  ASSERT_GT(force.norm(), 0.0);
  EXPECT_LE((shares - force).norm(), 1e-12 * force.norm());
}

// A load three times what closes the gap presses the plate onto the substrate (the statics with
// the contact as one of the frame's forces): the plate lies on the contact plane within the
// tolerance, and its four springs carry k delta, the rest going into the substrate. The anchors'
// reactions come from the members' end forces; the plate's place, and so the springs' force, is
// known to the tolerance, 1e-4 of the gap.
TEST(FrameSubstrateContactTest, APlateLoadedOntoTheSubstrateLiesOnItOnItsSprings) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  FrameSubstrateContact contact(model, Substrate());
  FrameLoadCase loads;
  loads.points.push_back(
      {-1, 0, Eigen::Vector3d(0.0, -3.0 * plate.k * kGap, 0.0), Eigen::Vector3d::Zero()});
  const FrameStaticSolution solution = SolveFrameNonlinearStatic(model, {&contact}, loads);
  ASSERT_EQ(solution.status, Status::kOk);
  EXPECT_NEAR(solution.bodies[0][1], -kGap, contact.tolerance());
  EXPECT_EQ(contact.Summary().state, ContactState::kContact);
  double carried = 0.0;
  for (const FrameReaction& reaction : solution.reactions) carried += reaction.force.y();
  EXPECT_NEAR(carried, plate.k * kGap, 1e-4 * plate.k * kGap);
}

}  // namespace
}  // namespace cosmems
