// The beam the hand touches, as the command line and the viewer touch it: the reference
// cantilever's one-member netlist (StraightBeam) on HapticStructure. A press on the tip against
// the closed form of two springs in series, the local model the servo loop extrapolates with,
// the other faces, a hard press onto the substrate, and "Reset Failure" of a beam laid down and
// stuck by the Casimir force.
#include <gtest/gtest.h>

#include <cmath>

#include "cosmems/haptics/haptic_structure.hpp"
#include "haptic_test_beam.hpp"

namespace cosmems {
namespace {

using test::kProbeRadius;
using test::kReferenceThickness;

using test::HapticCantileverNetlist;

// The tip's motion in a frame: u_y [m] and the slope r_z [rad].
double TipDeflection(const FrameModel& model, const HapticFrame& frame) {
  return test::NetlistTipDeflection(model, frame);
}
double TipSlope(const FrameModel& model, const HapticFrame& frame) {
  return frame.carrier_motion_m(5, model.mesh().nodes[1].carrier);
}

// The local model after `ticks` ticks of the probe `depth` over the tip's upper face.
const LocalModel& PressTip(HapticStructure& beam, double depth, int ticks) {
  for (int tick = 0; tick < ticks; ++tick) {
    EXPECT_EQ(beam.Advance(test::OverTip(depth), 0.0), Status::kOk);
  }
  return beam.local_model();
}

TEST(HapticStraightBeamTest, APressOnTheTipIsTwoSpringsInSeries) {
  const FrameModel model(HapticCantileverNetlist(true));
  const double k_c = 5.0, k_tip = test::ReferenceTipStiffness();
  HapticStructure beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                       test::TightPhysics());
  const double depth = 0.5e-6;
  const double series = k_c * k_tip / (k_c + k_tip);
  // Hermite elements are exact for a tip load; rho_inf = 0 leaves the static state after a few
  // 100 us steps, the first mode's period being 14.5 us. 1e-9: round-off in the internal units.
  const LocalModel& local = PressTip(beam, depth, 5);
  ASSERT_TRUE(local.valid);
  EXPECT_NEAR(local.force_n, series * depth, 1e-9 * series * depth);
  EXPECT_NEAR(local.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_EQ(local.clearance_m, 0.0);
  // The display's frame carries the tip's slope, with which it orients the faces: under a tip
  // load, theta_z(L) = F L^2 / (2 E I) = 3 w(L) / (2 L).
  const HapticFrame frame = beam.MakeFrame();
  const double tip_w = -series * depth / k_tip;
  EXPECT_NEAR(TipDeflection(model, frame), tip_w, -1e-9 * tip_w);
  EXPECT_NEAR(TipSlope(model, frame), 1.5 * tip_w / test::kReferenceLength,
              -1e-9 * tip_w / test::kReferenceLength);
  // The local model predicts the next press: the problem is linear, so exactly.
  const double deeper = 0.8e-6;
  const double predicted = local.ForceAt(test::OverTip(deeper)).y();
  EXPECT_NEAR(PressTip(beam, deeper, 5).force_n, predicted, 1e-9 * predicted);
  // Lifted 1 um clear: no force, the clearance is known.
  EXPECT_EQ(PressTip(beam, -1e-6, 5).force_n, 0.0);
  EXPECT_NEAR(beam.local_model().clearance_m, 1e-6, 1e-12);
}

// The modal path (analysis.integrator = "modal"): four modes with the probe's force held over
// each step and the truncated modes answering statically, damped as the real beam (Q = 100 at
// 68.8 kHz loses 0.9 of its ringing a tick). Once the press has rung down the hand feels the
// same two springs in series: the modal model's statics are the full model's. 1e-7: the
// truncated modes' flexibility K^-1 - Phi diag(1/w^2) Phi^T is a difference that loses digits.
TEST(HapticStraightBeamTest, TheModalPathFeelsTheSameSpringsOnceThePressHasRungDown) {
  const FrameModel model(HapticCantileverNetlist(true));
  const double k_c = 5.0, k_tip = test::ReferenceTipStiffness(), depth = 0.5e-6;
  HapticPhysicsOptions options;
  options.path = TimePath::kModal;
  options.modes = 4;
  options.damping = DampingModel::QualityFactor(100);
  HapticStructure beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                       test::TightPhysics(options));
  const LocalModel& local = PressTip(beam, depth, 20);
  const double series = k_c * k_tip / (k_c + k_tip);
  ASSERT_TRUE(local.valid);
  EXPECT_NEAR(local.force_n, series * depth, 1e-7 * series * depth);
  EXPECT_NEAR(local.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_GT(beam.last_stats().evaluations, 0);  // Newton held the probe's force
  // Lifted clear, the beam springs back and rings down to rest.
  EXPECT_EQ(PressTip(beam, -1e-6, 20).force_n, 0.0);
  EXPECT_LT(beam.displacement().norm(), 1e-7 * depth / model.units().length);
}

// The other faces: pushed up from under the tip, the beam is the same spring; pushed sideways at
// the tip of a spatial beam, it bends across its width, 3 E I_y / L^3 with I_y = t b^3 / 12, 100
// times stiffer, in series with the coupling.
TEST(HapticStraightBeamTest, UnderTheTipOrAtItsSideTheBeamIsTheSpringOfThatBending) {
  const double k_c = 5.0, depth = 0.5e-6;
  {
    const FrameModel model(HapticCantileverNetlist(true));
    HapticStructure beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                         test::TightPhysics());
    const Eigen::Vector3d under(test::kReferenceLength,
                                -0.5 * kReferenceThickness + depth - kProbeRadius, 0.0);
    for (int tick = 0; tick < 5; ++tick) ASSERT_EQ(beam.Advance(under, 0.0), Status::kOk);
    const double k_tip = test::ReferenceTipStiffness(), series = k_c * k_tip / (k_c + k_tip);
    const LocalModel& local = beam.local_model();
    EXPECT_EQ(local.normal, -Eigen::Vector3d::UnitY());
    // 1e-9: round-off in the internal units (the static state is exact, as above).
    EXPECT_NEAR(local.force_n, series * depth, 1e-9 * series * depth);
    EXPECT_NEAR(local.stiffness_n_per_m, series, 1e-9 * series);
    EXPECT_GT(TipDeflection(model, beam.MakeFrame()), 0.0);  // lifted
  }
  const FrameModel model(HapticCantileverNetlist(false), FrameCouplings::kTwist);
  HapticStructure beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                       test::TightPhysics());
  const double width = 20e-6;
  const Eigen::Vector3d beside(test::kReferenceLength, 0.0, 0.5 * width + kProbeRadius - depth);
  for (int tick = 0; tick < 5; ++tick) ASSERT_EQ(beam.Advance(beside, 0.0), Status::kOk);
  const double k_side = 100.0 * test::ReferenceTipStiffness(),
               series = k_c * k_side / (k_c + k_side);
  const LocalModel& local = beam.local_model();
  EXPECT_EQ(local.normal, Eigen::Vector3d::UnitZ());
  EXPECT_NEAR(local.force_n, series * depth, 1e-9 * series * depth);
  EXPECT_NEAR(local.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_NEAR(beam.MakeFrame().probe_force_n.z(), series * depth, 1e-9 * series * depth);
}

// A hand pressing the tip onto the substrate and 8 um on, four times the beam's thickness: the
// probe keeps pushing the beam down, never through it, and every tick converges.
TEST(HapticStraightBeamTest, AHardPressHoldsTheBeamOnTheSubstrate) {
  const FrameModel model(HapticCantileverNetlist(true));
  test::HapticNetlistSurface surface(model);
  HapticStructure beam(model, ProbeOptions{kProbeRadius, 20.0}, &surface.all, &surface.contact);
  for (int tick = 0; tick <= 400; ++tick) {
    const double depth = 10e-6 * std::min(1.0, tick / 300.0);
    ASSERT_EQ(beam.Advance(test::OverTip(depth), 0.0), Status::kOk) << tick;
    ASSERT_EQ(beam.local_model().normal, Eigen::Vector3d::UnitY()) << tick;
  }
  const HapticFrame frame = beam.MakeFrame();
  EXPECT_LT(TipDeflection(model, frame), -0.98 * test::kHapticGap);
  EXPECT_GT(frame.probe_force_n.y(), 0.0);
  EXPECT_TRUE(frame.contact.Stuck());
}

// Pressed onto the substrate at the tip, then swept toward the clamp, the stylus lays the beam
// down; lifted, it leaves it stuck in the S shape whose free span s balances the adhesion,
// Gamma = 3 E t^3 g^2 / (2 s^4): s = 142 um here. The frame shows the span (the one member's
// contact lengths) and "Reset Failure" frees the beam.
TEST(HapticStraightBeamTest, LaidDownByTheStylusItStaysStuckUntilReset) {
  const FrameModel model(HapticCantileverNetlist(true));
  const double gap = test::kHapticGap;
  // The Casimir pressure zips the beam down behind the probe.
  test::HapticNetlistSurface surface(model);
  // A stiff coupling (50 N/m, 60 times the tip's stiffness) lays the beam down within a 3 um
  // press; a softer one needs the hand to travel farther.
  HapticStructure beam(model, ProbeOptions{kProbeRadius, 50.0}, &surface.all, &surface.contact);
  auto at = [](double x, double depth) {
    return Eigen::Vector3d(x, 0.5 * kReferenceThickness - depth + kProbeRadius, 0.0);
  };
  const double depth = 3e-6;
  for (int tick = 0; tick <= 200; ++tick) {
    ASSERT_EQ(beam.Advance(at(test::kReferenceLength, depth * tick / 200.0), 0.0), Status::kOk);
  }
  for (int tick = 0; tick <= 200; ++tick) {  // sweep from the tip to midspan
    const double x = test::kReferenceLength * (1.0 - 0.5 * tick / 200.0);
    ASSERT_EQ(beam.Advance(at(x, depth), 0.0), Status::kOk);
  }
  for (int tick = 0; tick <= 200; ++tick) {  // lift 5 um clear
    ASSERT_EQ(beam.Advance(at(0.5 * test::kReferenceLength, depth - 8e-6 * tick / 200.0), 0.0),
              Status::kOk);
  }
  HapticFrame frame = beam.MakeFrame();
  EXPECT_TRUE(frame.contact.Stuck());
  EXPECT_EQ(frame.contact.shape, StuckShape::kS);
  EXPECT_EQ(beam.local_model().force_n, 0.0);
  // The S-shape's span within two 10 um elements (adhesion acts at the nodes).
  EXPECT_NEAR(frame.contact.detached_length_m, 142e-6, 20e-6);
  EXPECT_GT(frame.contact.contact_length_m, 0.0);
  EXPECT_LT(TipDeflection(model, frame), -0.9 * gap);
  EXPECT_GE(frame.events.stuck, 1);
  ASSERT_EQ(beam.Reset(), Status::kOk);
  ASSERT_EQ(beam.Advance(at(0.5 * test::kReferenceLength, -5e-6), 0.0), Status::kOk);
  beam.Fill(frame);
  EXPECT_EQ(frame.contact.state, ContactState::kFree);
  EXPECT_NEAR(frame.contact.detached_length_m, test::kReferenceLength,
              1e-12 * test::kReferenceLength);
  EXPECT_LT(std::abs(TipDeflection(model, frame)), 1e-3 * gap);
}

}  // namespace
}  // namespace cosmems
