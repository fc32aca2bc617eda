// The beam the hand touches: a press on the tip against the closed form of two springs in series,
// the local model the servo loop extrapolates with, and "Reset Failure" of a beam stuck by the
// Casimir force.
#include "cosmems/haptics/haptic_beam.hpp"

#include <gtest/gtest.h>

#include "haptic_test_beam.hpp"

namespace cosmems {
namespace {

using test::kProbeRadius;
using test::kReferenceThickness;

TEST(HapticBeamTest, APressOnTheTipIsTwoSpringsInSeries) {
  const BeamModel<2> model = test::HapticCantilever();
  const double k_c = 5.0, k_tip = test::ReferenceTipStiffness();
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                     test::TightPhysics());
  const double depth = 0.5e-6;
  for (int tick = 0; tick < 5; ++tick)
    ASSERT_EQ(beam.Advance(test::OverTip(depth), 0.0), Status::kOk);
  const double series = k_c * k_tip / (k_c + k_tip);
  // Hermite elements are exact for a tip load; rho_inf = 0 leaves the static state after a few
  // 100 us steps, the first mode's period being 14.5 us. 1e-9: round-off in the internal units.
  const LocalModel& local = beam.local_model();
  ASSERT_TRUE(local.valid);
  EXPECT_NEAR(local.force_n, series * depth, 1e-9 * series * depth);
  EXPECT_NEAR(local.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_EQ(local.clearance_m, 0.0);
  // The display's frame carries the slope at each node, with which it orients the faces: under a
  // tip load, theta_z(L) = F L^2 / (2 E I) = 3 w(L) / (2 L), and the clamp stays level.
  const HapticFrame frame = beam.MakeFrame();
  const double tip_w = -series * depth / k_tip;
  EXPECT_NEAR(frame.deflection_m[20], tip_w, -1e-9 * tip_w);
  EXPECT_NEAR(frame.rotation_rad[20], 1.5 * tip_w / test::kReferenceLength,
              -1e-9 * tip_w / test::kReferenceLength);
  EXPECT_EQ(frame.rotation_rad[0], 0.0);
  // The local model predicts the next press: the problem is linear, so exactly.
  const double deeper = 0.8e-6;
  const double predicted = local.ForceAt(test::OverTip(deeper)).y();
  for (int tick = 0; tick < 5; ++tick)
    ASSERT_EQ(beam.Advance(test::OverTip(deeper), 0.0), Status::kOk);
  EXPECT_NEAR(beam.local_model().force_n, predicted, 1e-9 * predicted);
  // Lifted 1 um clear: no force, the clearance is known.
  for (int tick = 0; tick < 5; ++tick)
    ASSERT_EQ(beam.Advance(test::OverTip(-1e-6), 0.0), Status::kOk);
  EXPECT_EQ(beam.local_model().force_n, 0.0);
  EXPECT_NEAR(beam.local_model().clearance_m, 1e-6, 1e-12);
}

// The modal path (analysis.integrator = "modal"): four modes with the probe's force held over
// each step and the truncated modes answering statically, damped as the real beam (Q = 100 at
// 68.8 kHz loses 0.9 of its ringing a tick). Once the press has rung down the hand feels the
// same two springs in series: the modal model's statics are the full model's. 1e-7: the
// truncated modes' flexibility K^-1 - Phi diag(1/w^2) Phi^T is a difference that loses digits.
TEST(HapticBeamTest, TheModalPathFeelsTheSameSpringsOnceThePressHasRungDown) {
  const BeamModel<2> model = test::HapticCantilever();
  const double k_c = 5.0, k_tip = test::ReferenceTipStiffness(), depth = 0.5e-6;
  HapticPhysicsOptions options;
  options.path = TimePath::kModal;
  options.modes = 4;
  options.damping = DampingModel::QualityFactor(100);
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                     test::TightPhysics(options));
  for (int tick = 0; tick < 20; ++tick)
    ASSERT_EQ(beam.Advance(test::OverTip(depth), 0.0), Status::kOk);
  const double series = k_c * k_tip / (k_c + k_tip);
  const LocalModel& local = beam.local_model();
  ASSERT_TRUE(local.valid);
  EXPECT_NEAR(local.force_n, series * depth, 1e-7 * series * depth);
  EXPECT_NEAR(local.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_GT(beam.last_stats().evaluations, 0);  // Newton held the probe's force
  // Lifted clear, the beam springs back and rings down to rest.
  for (int tick = 0; tick < 20; ++tick)
    ASSERT_EQ(beam.Advance(test::OverTip(-1e-6), 0.0), Status::kOk);
  EXPECT_EQ(beam.local_model().force_n, 0.0);
  EXPECT_LT(beam.displacement().norm(), 1e-7 * depth / model.units().length);
}

// The other faces: pushed up from under the tip, the beam is the same spring; pushed sideways at
// the tip of a 3-D beam, it bends across its width, 3 E I_z / L^3 with I_z = t b^3 / 12, 100 times
// stiffer, in series with the coupling.
TEST(HapticBeamTest, UnderTheTipOrAtItsSideTheBeamIsTheSpringOfThatBending) {
  const double k_c = 5.0, depth = 0.5e-6;
  {
    const BeamModel<2> model = test::HapticCantilever();
    HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
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
    EXPECT_GT(beam.MakeFrame().deflection_m[20], 0.0);  // lifted
  }
  const BeamModel<3> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 0));
  HapticBeam<3> beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
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
TEST(HapticBeamTest, AHardPressHoldsTheBeamOnTheSubstrate) {
  const BeamModel<2> model = test::HapticCantilever();
  test::HapticSurface forces = test::MakeHapticSurface(model);
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, 20.0}, &forces, &forces.get<0>());
  for (int tick = 0; tick <= 400; ++tick) {
    const double depth = 10e-6 * std::min(1.0, tick / 300.0);
    ASSERT_EQ(beam.Advance(test::OverTip(depth), 0.0), Status::kOk) << tick;
    ASSERT_EQ(beam.local_model().normal, Eigen::Vector3d::UnitY()) << tick;
  }
  const HapticFrame frame = beam.MakeFrame();
  EXPECT_LT(frame.deflection_m[20], -0.98 * test::kHapticGap);
  EXPECT_GT(frame.probe_force_n.y(), 0.0);
  EXPECT_TRUE(frame.contact.Stuck());
}

// Pressed on the tip's upper face z0 off the axis, a 3-D beam numbered node by node bends and
// twists: the point under the probe sinks F (L^3 / 3EI + z0^2 L / GJ), in series with the
// coupling.
TEST(HapticBeamTest, APressOffTheAxisTwistsTheBeam) {
  const BeamModel<3> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 0),
                           DofNumbering::kByNode);
  const double k_c = 5.0, depth = 0.5e-6, z0 = 8e-6;
  HapticBeam<3> beam(model, ProbeOptions{kProbeRadius, k_c}, nullptr, nullptr,
                     test::TightPhysics());
  const Eigen::Vector3d centre = test::OverTip(depth) + Eigen::Vector3d(0.0, 0.0, z0);
  for (int tick = 0; tick < 5; ++tick) ASSERT_EQ(beam.Advance(centre, 0.0), Status::kOk);
  const Material silicon = test::Silicon();
  const double shear = silicon.young_modulus / (2.0 * (1.0 + silicon.poisson_ratio));
  const double torsion =
      shear * test::ReferenceSection().TorsionConstant() / test::kReferenceLength;
  const double compliance = 1.0 / test::ReferenceTipStiffness() + z0 * z0 / torsion + 1.0 / k_c;
  // Hermite bending and linear torsion are exact for end loads; 1e-9: round-off, as above.
  EXPECT_NEAR(beam.local_model().force_n, depth / compliance, 1e-9 * depth / compliance);
  EXPECT_NEAR(beam.local_model().stiffness_n_per_m, 1.0 / compliance, 1e-9 / compliance);
}

// Pressed onto the substrate at the tip, then swept toward the clamp, the stylus lays the beam
// down; lifted, it leaves it stuck in the S shape whose free span s balances the adhesion,
// Gamma = 3 E t^3 g^2 / (2 s^4): s = 142 um here.
TEST(HapticBeamTest, LaidDownByTheStylusItStaysStuckUntilReset) {
  const BeamModel<2> model = test::HapticCantilever();
  const double gap = test::kHapticGap;
  // The Casimir pressure zips the beam down behind the probe.
  test::HapticSurface forces = test::MakeHapticSurface(model);
  // A stiff coupling (50 N/m, 60 times the tip's stiffness) lays the beam down within a 3 um
  // press; a softer one needs the hand to travel farther.
  HapticBeam<2> beam(model, ProbeOptions{kProbeRadius, 50.0}, &forces, &forces.get<0>());
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
  EXPECT_EQ(beam.local_model().force_n, 0.0);
  // The S-shape's span within two 10 um elements (adhesion acts at the nodes).
  EXPECT_NEAR(frame.contact.detached_length_m, 142e-6, 20e-6);
  EXPECT_LT(frame.deflection_m[20], -0.9 * gap);
  EXPECT_GE(frame.events.stuck, 1);
  ASSERT_EQ(beam.Reset(), Status::kOk);
  ASSERT_EQ(beam.Advance(at(0.5 * test::kReferenceLength, -5e-6), 0.0), Status::kOk);
  beam.Fill(frame);
  EXPECT_EQ(frame.contact.state, ContactState::kFree);
  EXPECT_LT(std::abs(frame.deflection_m[20]), 1e-3 * gap);
}

}  // namespace
}  // namespace cosmems
