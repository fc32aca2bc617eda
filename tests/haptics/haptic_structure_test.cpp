// The hand on any structure: presses that feel the suspension's closed-form stiffness in series
// with the coupling, on a cantilever member (bending, and bending with twist off the axis), a
// plate on four beams and a folded flexure's shuttle; the tick's first push, its start, its
// tolerance and its landing.
#include "cosmems/haptics/haptic_structure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/structure/folded_flexure.hpp"
#include "cosmems/surface/frame_gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "force_differences.hpp"
#include "haptics/haptic_test_beam.hpp"
#include "structure/test_frames.hpp"
#include "surface/plate_on_four_beams.hpp"

namespace cosmems {
namespace {

constexpr double kRadius = 2e-6;  // m, the probe as thick as the members

// The reference cantilever (silicon, 200 x 20 x 2 um, 20 elements) as a one-member frame.
StructureDescription CantileverFrame() {
  StructureDescription s;
  const int root = test::AddNode(s, "root", Eigen::Vector3d::Zero(), Support::kClamped);
  const int tip = test::AddNode(s, "tip", Eigen::Vector3d(test::kReferenceLength, 0.0, 0.0));
  s.members.push_back(
      {root, tip, test::Silicon(), test::ReferenceSection(), 20, Eigen::Vector3d::UnitY()});
  s.series_order = 0;  // Hermite elements, as the beam's
  return s;
}

// Pressed over the tip at several depths and lifted off, the member gives as the clamped
// cantilever's tip, 3EI/L^3, in series with the coupling; the elements are exact for a tip
// force, so the statics hold to Newton's tight tolerance (1e-9).
TEST(HapticStructureTest, ACantileverMemberIsPressedAsTheClosedForm) {
  const FrameModel frame(CantileverFrame());
  HapticStructure structure(frame, ProbeOptions{test::kProbeRadius, 5.0}, nullptr, nullptr,
                            test::TightPhysics());
  const double series = 5.0 * test::ReferenceTipStiffness() / (5.0 + test::ReferenceTipStiffness());
  for (const double depth : {0.5e-6, 0.8e-6, 0.2e-6, -1e-6}) {
    for (int tick = 0; tick < 5; ++tick) {
      ASSERT_EQ(structure.Advance(test::OverTip(depth), 0.0), Status::kOk);
    }
    const LocalModel& a = structure.local_model();
    ASSERT_TRUE(a.valid);
    EXPECT_NEAR(a.force_n, series * std::max(0.0, depth), 1e-9 * series * 1e-6) << depth;
    if (depth > 0.0) {
      EXPECT_NEAR(a.stiffness_n_per_m, series, 1e-9 * series) << depth;
      EXPECT_TRUE(a.normal.isApprox(Eigen::Vector3d::UnitY(), 1e-12));
    } else {  // lifted 1 um: the clearance is the lift, the member back at rest (to 1e-6 of it)
      EXPECT_NEAR(a.clearance_m, -depth, 1e-12);
    }
  }
  EXPECT_EQ(structure.DofCount(), 6 * 20);
}

// A press off the axis twists a spatial member when its numbering keeps the twist
// (FrameCouplings::kTwist): pressed at the tip z off the axis, the cantilever's upper face gives
// as bending and torsion in series, 1/k = L^3/(3 E I) + z^2 L/(G J) (about 1 % from the twist
// here), felt in series with the coupling. The elements are exact for a tip force and a uniform
// torque, so both hold to Newton's tight tolerance (1e-9). Numbered without the twist, the
// same press feels the bending alone.
TEST(HapticStructureTest, AnOffAxisPressTwistsASpatialMember) {
  const double k_c = 5.0, depth = 0.3e-6, z = 8e-6;
  const RectangularSection section = test::ReferenceSection();
  const Material silicon = test::Silicon();
  const double l = test::kReferenceLength;
  const double bending = l * l * l / (3.0 * silicon.young_modulus * section.SecondMomentZ());
  const double twist = z * z * l / (silicon.ShearModulus() * section.TorsionConstant());
  const Eigen::Vector3d centre = test::OverTip(depth) + Eigen::Vector3d(0.0, 0.0, z);
  for (const FrameCouplings couplings : {FrameCouplings::kTwist, FrameCouplings::kLinear}) {
    const FrameModel model(CantileverFrame(), couplings);
    HapticStructure structure(model, ProbeOptions{test::kProbeRadius, k_c}, nullptr, nullptr,
                              test::TightPhysics());
    for (int tick = 0; tick < 6; ++tick) ASSERT_EQ(structure.Advance(centre, 0.0), Status::kOk);
    const double compliance = couplings == FrameCouplings::kTwist ? bending + twist : bending;
    const double series = k_c / (1.0 + k_c * compliance);
    EXPECT_NEAR(structure.local_model().stiffness_n_per_m, series, 1e-9 * series);
    EXPECT_NEAR(structure.local_model().force_n, series * depth, 1e-9 * series * depth);
  }
}

// The probe pressing the point `face_m` of an upper face `depth` deep from above, on the
// structure, until it has settled (rho_inf = 0 leaves the static state after a few ticks, the
// devices' first modes being near 100 kHz): the force and the local model's stiffness.
struct Press {
  double force_n, stiffness_n_per_m;
};
Press PressAt(HapticStructure& structure, const Eigen::Vector3d& centre) {
  for (int tick = 0; tick < 6; ++tick) EXPECT_EQ(structure.Advance(centre, 0.0), Status::kOk);
  EXPECT_TRUE(structure.local_model().valid);
  return {structure.local_model().force_n, structure.local_model().stiffness_n_per_m};
}

TEST(HapticStructureTest, APlateOnFourBeamsIsItsSuspensionInSeriesWithTheCoupling) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  const double k_c = 5.0 * plate.k, depth = 0.4e-6;
  HapticStructure structure(model, ProbeOptions{kRadius, k_c}, nullptr, nullptr,
                            test::TightPhysics());
  const Press press = PressAt(structure, {0.0, 1e-6 + kRadius - depth, 0.0});
  const double series = k_c * plate.k / (k_c + plate.k);
  // The frame is exact for the clamped-guided beams to 1e-10 (frame_model_test.cpp).
  EXPECT_NEAR(press.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_NEAR(press.force_n, series * depth, 1e-9 * series * depth);
  EXPECT_TRUE(structure.local_model().normal.isApprox(Eigen::Vector3d::UnitY()));
  // Lifted 1 um clear, the plate springs back: no force, the clearance known.
  PressAt(structure, {0.0, 1e-6 + kRadius + 1e-6, 0.0});
  EXPECT_EQ(structure.local_model().force_n, 0.0);
  EXPECT_NEAR(structure.local_model().clearance_m, 1e-6, 1e-12);
}

// What the display draws: the frame's motion of each carrier, the pressed plate sunk by the
// probe's force over its suspension's stiffness, without a tilt (pressed at its centre), and the
// anchors' nodes still.
TEST(HapticStructureTest, TheFrameShowsThePlateSunkByTheForceOverItsStiffness) {
  const test::PlateOnFourBeams plate;
  const FrameModel model(plate.structure);
  HapticStructure structure(model, ProbeOptions{kRadius, 5.0 * plate.k}, nullptr, nullptr,
                            test::TightPhysics());
  const Press press = PressAt(structure, {0.0, 1e-6 + kRadius - 0.4e-6, 0.0});
  HapticFrame frame = structure.MakeFrame();
  ASSERT_EQ(frame.carrier_motion_m.cols(), static_cast<Eigen::Index>(model.mesh().carriers.size()));
  const Eigen::Matrix<double, 6, 1> body = frame.carrier_motion_m.col(model.mesh().body_carrier[0]);
  const double sunk = press.force_n / plate.k;
  EXPECT_NEAR(body[1], -sunk, 1e-9 * sunk);
  EXPECT_LT(body.tail<3>().norm(), 1e-9 * sunk / 1e-6);
  for (std::size_t c = 0; c < model.mesh().carriers.size(); ++c) {
    if (model.mesh().carriers[c].anchor == AnchorMask{true, true, true, true, true, true}) {
      EXPECT_EQ(frame.carrier_motion_m.col(static_cast<Eigen::Index>(c)).norm(), 0.0);
    }
  }
}

TEST(HapticStructureTest, APushOnTheShuttlesSideMeetsTheFlexuresInPlaneStiffness) {
  FoldedFlexureDesign design;
  design.material = test::Poly();
  design.elements = 4;
  const FrameModel model(FoldedFlexure(design));
  const double k_x = design.Stiffness(), k_c = 5.0 * k_x, depth = 0.3e-6;
  HapticStructure structure(model, ProbeOptions{kRadius, k_c}, nullptr, nullptr,
                            test::TightPhysics());
  // The +x side of the 40 um shuttle, on its centre line: a push along -x without a turn.
  const Press press = PressAt(structure, {20e-6 + kRadius - depth, 0.0, 0.0});
  const double series = k_c * k_x / (k_c + k_x);
  // 24 E I / L^3 with rigid trusses, exact to 1e-10 in the frame (frame_model_test.cpp).
  EXPECT_NEAR(press.stiffness_n_per_m, series, 1e-9 * series);
  EXPECT_NEAR(press.force_n, series * depth, 1e-9 * series * depth);
  EXPECT_TRUE(structure.local_model().normal.isApprox(Eigen::Vector3d::UnitX()));
}

// The resonator's effects, Casimir and the substrate's contact, passed on with the multiplier
// updates inside steps counted (Settle() changing the state) and the update between steps
// (NonlinearForce::StartStep) passed on or withheld; the pressure `held` at the contact's
// separation from below, as scenes build it, or growing through the contact's penetration.
class CountedEffects final : public NonlinearForce {
 public:
  CountedEffects(const FrameModel& model, const ContactOptions& substrate, bool start_steps,
                 bool held)
      : casimir_(model, CasimirPressure{}, Under(substrate, held)),
        contact_(model, substrate),
        start_steps_(start_steps) {
    forces_.Add(casimir_);
    forces_.Add(contact_);
  }
  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& r, ForceTangent& t) override {
    ++evaluations;
    return forces_.Evaluate(d, r, t);
  }
  bool Idle(const Eigen::VectorXd& d) const override { return forces_.Idle(d); }
  bool Settle(const Eigen::VectorXd& d) override {
    const bool settled = forces_.Settle(d);
    if (!settled) ++updates_inside;
    return settled;
  }
  void Commit(const Eigen::VectorXd& d) override { forces_.Commit(d); }
  void Revert() override { forces_.Revert(); }
  void StartStep() override {
    if (start_steps_) forces_.StartStep();
  }
  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    forces_.ProjectMotion(d, v, a);
  }
  FrameSubstrateContact& contact() { return contact_; }

  long evaluations = 0, updates_inside = 0;

 private:
  static FrameGapOptions Under(const ContactOptions& substrate, bool held) {
    FrameGapOptions under{substrate.gap};
    if (held) under.separation = substrate.separation;
    return under;
  }

  FrameGapForce<CasimirPressure> casimir_;
  FrameSubstrateContact contact_;
  ForceSum forces_;
  bool start_steps_;
};

// The resonator's shuttle pressed onto the substrate 2 um below it (coupling 50 N/m, 4 um deep)
// with contact, stiction (Gamma = 1e-6 J/m^2) and the Casimir force, and lifted 1 um clear,
// over 500 ticks, as the tick benchmark presses it, at one set of physics options.
struct PressedResonator {
  static constexpr int kTicks = 500;
  static ContactOptions Substrate() {
    ContactOptions substrate;
    substrate.gap = 2e-6;
    substrate.separation = 1e-2 * substrate.gap;
    substrate.stiction = true;
    substrate.adhesion_energy = 1e-6;
    return substrate;
  }
  static HapticPhysicsOptions Physics() {
    HapticPhysicsOptions haptic;
    haptic.damping = DampingModel::QualityFactor(100);
    return haptic;
  }
  PressedResonator(const FrameModel& model, const HapticPhysicsOptions& physics,
                   bool start_steps = true, bool held = false)
      : effects(model, Substrate(), start_steps, held),
        structure(model, ProbeOptions{kRadius, 50.0}, &effects, &effects.contact(), physics) {}
  Status Tick(int tick) {
    const double s = static_cast<double>(tick) / kTicks;
    const double depth = s < 0.5 ? 4e-6 * s / 0.5 : 4e-6 - 5e-6 * (s - 0.5) / 0.5;
    return structure.Advance(Eigen::Vector3d(3e-6, 3e-6 - depth, 5e-6), 0.0);
  }
  double force_n() const { return structure.local_model().force_n; }

  CountedEffects effects;
  HapticStructure structure;
};

// The pressed resonator's first push factors at once: ProbedPhysics forgets the factor kept from
// before, formed without the sphere's spring (tick 0 has the sphere on the shuttle's face, not yet
// pushing). Measured before: 4 evaluations and 2 factorisations (the kept factor's corrections
// overshot past the probe, where a fresh matrix had no spring either).
TEST(HapticStructureTest, TheFirstPushFactorsAtOnce) {
  const FrameModel model(FoldedFlexure(FoldedFlexureDesign{}));
  PressedResonator pressed(model, PressedResonator::Physics());
  ASSERT_EQ(pressed.Tick(0), Status::kOk);
  EXPECT_EQ(pressed.force_n(), 0.0);
  ASSERT_EQ(pressed.Tick(1), Status::kOk);
  EXPECT_GT(pressed.force_n(), 0.0);
  EXPECT_EQ(pressed.structure.last_stats().factorizations, 1);
  EXPECT_EQ(pressed.structure.last_stats().evaluations, 2);
}

// The tick after the first push starts Newton from its start: the velocity the first push left
// would predict the shuttle 4.3 nm clear of the sphere it lies 1.5 nm into, where the factor kept
// with the sphere's spring no longer fits the forces and a fresh one without it overshoots back
// into the spring. Measured before: 4 evaluations and 2 factorisations; from the step's start
// the kept factor serves.
TEST(HapticStructureTest, TheTickAfterTheFirstPushStartsWhereTheShuttleIs) {
  const FrameModel model(FoldedFlexure(FoldedFlexureDesign{}));
  PressedResonator pressed(model, PressedResonator::Physics());
  for (int tick = 0; tick < 2; ++tick) ASSERT_EQ(pressed.Tick(tick), Status::kOk);
  ASSERT_EQ(pressed.Tick(2), Status::kOk);
  EXPECT_GT(pressed.force_n(), 0.0);
  EXPECT_EQ(pressed.structure.last_stats().factorizations, 0);
  EXPECT_EQ(pressed.structure.last_stats().evaluations, 2);
}

// Options Validate() must refuse with a message naming `field`.
void ExpectRefusedByName(const HapticPhysicsOptions& options, const std::string& field) {
  try {
    options.Validate();
    ADD_FAILURE() << field << " accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
  }
}

// The haptic tolerance against a tight one: the pressed resonator at Newton's haptic residual
// tolerance (1e-6) and at 1e-10. Each leaves the shuttle on the substrate within the contact's
// tolerance (1e-4 of the gap), so the probe's forces may differ by the coupling (50 N/m) times
// twice that, 2e-8 N (2e-4 of the largest); they stay within it tick by tick (measured 2.2e-9 N),
// with the same contact and stuck events.
TEST(HapticStructureTest, TheHapticToleranceFeelsAsTheTightOne) {
  const FrameModel model(FoldedFlexure(FoldedFlexureDesign{}));
  const HapticPhysicsOptions haptic = PressedResonator::Physics();
  HapticPhysicsOptions tight = haptic;
  tight.residual_tolerance = 1e-10;
  tight.predicted_increment_tolerance = 0.0;  // every tick ends on an evaluated residual
  PressedResonator a(model, haptic), b(model, tight);
  double largest = 0.0, differs = 0.0;
  for (int tick = 0; tick < PressedResonator::kTicks; ++tick) {
    ASSERT_EQ(a.Tick(tick), Status::kOk) << tick;
    ASSERT_EQ(b.Tick(tick), Status::kOk) << tick;
    largest = std::max(largest, std::abs(b.force_n()));
    differs = std::max(differs, std::abs(a.force_n() - b.force_n()));
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(differs, 50.0 * 2.0 * a.effects.contact().tolerance());
  const ContactEvents& events = a.effects.contact().events();
  EXPECT_EQ(events.contacts, b.effects.contact().events().contacts);
  EXPECT_EQ(events.stuck, 1);
  EXPECT_EQ(events.stuck, b.effects.contact().events().stuck);
  EXPECT_EQ(events.releases, b.effects.contact().events().releases);
  // A tolerance no step could meet, or one that feels nothing, is refused by name.
  for (const double bad : {0.0, 1e-2}) {
    HapticPhysicsOptions refused = haptic;
    refused.residual_tolerance = bad;
    ExpectRefusedByName(refused, "residual_tolerance");
  }
}

// A tick whose kept factor's correction is small and predicted to leave the residual within the
// tolerance ends without a last evaluation (HapticPhysicsOptions::predicted_increment_tolerance):
// against the same press ending every tick on an evaluated residual and against the tight solve
// (1e-10), over two cycles, the probe's forces stay within the bound above, with the same events,
// for fewer force evaluations. Measured: the forces of the evaluated press exactly (every
// prediction held, so every tick ended at the same iterate), 3.9e-11 N from the tight solve's,
// 1163 evaluations against 1634.
TEST(HapticStructureTest, APredictedCorrectionEndsATickAsAnEvaluatedOneWould) {
  const FrameModel model(FoldedFlexure(FoldedFlexureDesign{}));
  const HapticPhysicsOptions haptic = PressedResonator::Physics();
  HapticPhysicsOptions evaluated = haptic, tight = haptic;
  evaluated.predicted_increment_tolerance = 0.0;
  tight.predicted_increment_tolerance = 0.0;
  tight.residual_tolerance = 1e-10;
  PressedResonator a(model, haptic), b(model, evaluated), c(model, tight);
  double from_evaluated = 0.0, from_tight = 0.0;
  for (int tick = 0; tick < 2 * PressedResonator::kTicks; ++tick) {
    const int cycle_tick = tick % PressedResonator::kTicks;
    ASSERT_EQ(a.Tick(cycle_tick), Status::kOk) << tick;
    ASSERT_EQ(b.Tick(cycle_tick), Status::kOk) << tick;
    ASSERT_EQ(c.Tick(cycle_tick), Status::kOk) << tick;
    from_evaluated = std::max(from_evaluated, std::abs(a.force_n() - b.force_n()));
    from_tight = std::max(from_tight, std::abs(a.force_n() - c.force_n()));
  }
  const double bound = 50.0 * 2.0 * a.effects.contact().tolerance();
  EXPECT_LE(from_evaluated, bound);
  EXPECT_LE(from_tight, bound);
  EXPECT_LT(a.effects.evaluations, 0.8 * b.effects.evaluations);
  for (PressedResonator* other : {&b, &c}) {
    const ContactEvents& events = other->effects.contact().events();
    EXPECT_EQ(a.effects.contact().events().contacts, events.contacts);
    EXPECT_EQ(a.effects.contact().events().stuck, events.stuck);
    EXPECT_EQ(a.effects.contact().events().releases, events.releases);
  }
  // A negative share, or one that would end a tick on a correction of a thousandth of the state,
  // is refused by name.
  for (const double bad : {-1e-6, 1e-2}) {
    HapticPhysicsOptions refused = haptic;
    refused.predicted_increment_tolerance = bad;
    ExpectRefusedByName(refused, "predicted_increment_tolerance");
  }
}

// A step starts from the multipliers at the reactions it starts from (StartStep): the pressed
// resonator then needs no multiplier update inside a step, where without it it needs one every
// ten pressed ticks or so, each restarting Newton (measured 44 in 1000 ticks, 2366 force
// evaluations against 1589). The two differ by where each leaves the shuttle within the contact's
// tolerance (1e-4 of the gap), so the probe's forces by at most the coupling times twice that.
TEST(HapticStructureTest, StepsStartingAtTheCommittedReactionsNeedNoUpdateInside) {
  const FrameModel model(FoldedFlexure(FoldedFlexureDesign{}));
  const HapticPhysicsOptions haptic = PressedResonator::Physics();
  PressedResonator with(model, haptic), without(model, haptic, false);
  double differs = 0.0;
  for (int tick = 0; tick < 2 * PressedResonator::kTicks; ++tick) {
    const int cycle_tick = tick % PressedResonator::kTicks;
    ASSERT_EQ(with.Tick(cycle_tick), Status::kOk) << tick;
    ASSERT_EQ(without.Tick(cycle_tick), Status::kOk) << tick;
    differs = std::max(differs, std::abs(with.force_n() - without.force_n()));
  }
  EXPECT_EQ(with.effects.updates_inside, 0);
  EXPECT_GE(without.effects.updates_inside, 10);
  EXPECT_LT(with.effects.evaluations, 0.8 * without.effects.evaluations);
  const double tolerance = with.effects.contact().tolerance();
  EXPECT_LE(differs, 50.0 * 2.0 * tolerance);
  EXPECT_EQ(with.effects.contact().events().stuck, without.effects.contact().events().stuck);
}

// The press with the Casimir pressure held at the contact's separation from below, as scenes
// build it: the pressure's stiffness then jumps at the contact plane, and on the landing a kept
// factor's correction threw the shuttle deep through it, from where Newton's fresh factors
// cycled (measured before the driver undid such corrections: 38 corrections, 48 factorisations
// and two cut steps in one tick, 87 factorisations in all over two cycles). Undoing them
// (NewtonDriver) lands it without a cut (measured: 39 factorisations at the former
// reuse_contraction 1e-3, 29 at the haptic 0.1), with the same stuck event.
TEST(HapticStructureTest, AHeldPressureLandsWithoutACutStep) {
  const FrameModel model(FoldedFlexure(FoldedFlexureDesign{}));
  PressedResonator pressed(model, PressedResonator::Physics(), /*start_steps=*/true,
                           /*held=*/true);
  NewtonStats total;
  for (int tick = 0; tick < 2 * PressedResonator::kTicks; ++tick) {
    ASSERT_EQ(pressed.Tick(tick % PressedResonator::kTicks), Status::kOk) << tick;
    total += pressed.structure.last_stats();
  }
  EXPECT_EQ(total.cuts, 0);
  EXPECT_LT(total.factorizations, 35);  // between the two measured counts
  EXPECT_EQ(pressed.effects.contact().events().stuck, 1);
  // A rule that keeps a factor contracting by less than half, or a negative one, is refused by
  // name.
  for (const double bad : {-0.1, 0.9}) {
    HapticPhysicsOptions refused = PressedResonator::Physics();
    refused.reuse_contraction = bad;
    ExpectRefusedByName(refused, "reuse_contraction");
  }
}

}  // namespace
}  // namespace cosmems
