// Passivity of the whole touch: a scripted hand (a spring-damper pulling a 45 g stylus) pushes the
// probe down until the beam lies on the substrate and holds it there, pressed against the stiff
// contact, for 10 s. A passive loop never gives the hand more energy than the hand put in: the
// work the device does on the hand, summed from the start, stays at or below zero. An active one
// (sampling, the coupling, contact switching) would show as growing oscillation and positive work.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cosmems/core/constants.hpp"
#include "cosmems/scripted/scripted_device.hpp"
#include "reference_touch.hpp"

namespace cosmems {
namespace {

// The script: from the device's centre down 23 mm (the probe through its 2 um clearance and the
// 2 um gap, then into the contact) in 0.3 s along a raised cosine, held there to 10 s. The hand
// spring pulls the stylus after it; the contact, felt at 350 N/m, stops it short.
class PressAndHold final : public Trajectory {
 public:
  Eigen::Vector3d Position(double t_s) const override {
    const double s = std::clamp(t_s / 0.3, 0.0, 1.0);
    return Eigen::Vector3d(0.0, -0.023 * 0.5 * (1.0 - std::cos(kPi * s)), 0.0);
  }
  double Duration() const override { return 10.0; }
};

// Run twice: with the passivity controller off, the loop itself (beam, coupling, contact, the
// zero-order hold) must be passive, since nothing else would hide an active part; with it on, a
// passive loop must never need it.
TEST(HapticPassivityTest, AHandHeldAgainstTheSubstrateGainsNoEnergyOver10Seconds) {
  for (const bool controller : {false, true}) {
    SCOPED_TRACE(controller ? "passivity controller on" : "passivity controller off");
    // The coupling felt at half the device's renderable stiffness (350 N/m): the stiff contact.
    test::ReferenceTouch touch;
    HapticLoop& loop = touch.loop;
    ScriptedOptions scripted;
    scripted.clock = ScriptedClock::kManual;
    scripted.hand = HandModel::kSpring;
    scripted.specs = touch.specs;
    scripted.safety.passivity_control = controller;
    ScriptedDevice device(std::make_unique<PressAndHold>(), scripted);
    ASSERT_EQ(device.Open(), DeviceStatus::kOk);
    ASSERT_EQ(device.Start(loop), DeviceStatus::kOk);
    device.Step(10001);  // 10 s at 1 kHz
    device.Stop();
    ASSERT_EQ(loop.failed_ticks(), 0u);
    ASSERT_TRUE(loop.UpdateFrame());
    EXPECT_TRUE(loop.frame().contact.InContact());  // the hand pressed the beam onto the substrate
    EXPECT_EQ(device.safety_counters().passivity_activations, 0);
    double work = 0.0, largest = 0.0, peak_force = 0.0, fastest = 0.0;
    for (const ScriptedSample& s : device.Recorded()) {
      work += s.force_n.dot(s.velocity_m_s) * 1e-3;
      largest = std::max(largest, work);
      peak_force = std::max(peak_force, s.force_n.norm());
      fastest = std::max(fastest, s.velocity_m_s.norm());
    }
    EXPECT_GT(peak_force, 0.3);  // the contact was felt
    // The slack: one tick of the largest force over the stylus's fastest motion (the zero-order
    // hold's sampling error).
    EXPECT_LE(largest, peak_force * fastest * 1e-3) << "work done on the hand: " << work << " J";
    const std::string run = controller ? "controller_on_" : "controller_off_";
    RecordProperty(run + "largest_work_j", std::to_string(largest));
    RecordProperty(run + "final_work_j", std::to_string(work));
    RecordProperty(run + "peak_force_n", std::to_string(peak_force));
  }
}

}  // namespace
}  // namespace cosmems
