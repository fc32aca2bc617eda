// The torsional micromirror's generator: a torque about the beams' axis twists them uniformly,
// which the frame's Saint-Venant torsion models exactly (round-off against 2 G J / L and the
// oracle); the torsion mode against Rayleigh's quotient with the beams' linear twist.
#include <gtest/gtest.h>

#include <algorithm>

#include "device_checks.hpp"

namespace cosmems {
namespace {

constexpr double kMirrorTorque = 1e-12;  // N m about x at the plate's centre

TEST(TorsionalMicromirrorTest, ATorqueTurnsItBy2GJOverLAndTheOracles) {
  TorsionalMicromirrorDesign design;
  design.elements = 2;
  const StructureDescription s = TorsionalMicromirror(design);
  const test::BodyMotion turned = test::SolveBodyMotion(s, 0, {0, 0, 0}, {kMirrorTorque, 0, 0});
  const test::BodyMotion oracle = test::OracleBodyMotion(s, 0, {0, 0, 0}, {kMirrorTorque, 0, 0});
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(turned[k], oracle[k], 1e-9 * turned[3]);
  EXPECT_NEAR(kMirrorTorque / turned[3], design.Stiffness(), 1e-9 * design.Stiffness());
  // The library's J (Roark's series), as the frame's members take it.
  const RectangularSection section{design.beam_width, design.thickness};
  EXPECT_EQ(design.Stiffness(),
            2 * design.material.ShearModulus() * section.TorsionConstant() / design.beam_length);
}

// The beams' rotary inertia is 1e-5 of the plate's here, and the quotient's error is of its
// square: measured 6.8e-11 (100 um beams) and 1.5e-10 (150 um), the series' discretisation at
// 8 elements; 1e-8 asserted.
TEST(TorsionalMicromirrorTest, TheTorsionModeRingsAtTheClosedForm) {
  TorsionalMicromirrorDesign design;
  for (double length : {100e-6, 150e-6}) {
    design.beam_length = length;
    ModalOptions options;
    options.count = 4;
    const FrameModalResult modes =
        SolveFrameModal(FrameModel(TorsionalMicromirror(design)), options);
    ASSERT_EQ(modes.modal.status, Status::kOk);
    const auto torsion = std::find_if(modes.modal.modes.begin(), modes.modal.modes.end(),
                                      [](const Mode& m) { return m.kind == ModeKind::kTorsion; });
    ASSERT_NE(torsion, modes.modal.modes.end());
    const double expected = design.NaturalFrequency();
    EXPECT_NEAR(torsion->frequency_hz, expected, 1e-8 * expected) << length;
    EXPECT_GT(modes.participation[torsion - modes.modal.modes.begin()][3], 0.999);
  }
  design.elements = 3;
  test::ExpectModesMatchOracle(TorsionalMicromirror(design), 4);
}

TEST(TorsionalMicromirrorTest, ParameterErrorsNameTheirKey) {
  auto field = [](void (*change)(TorsionalMicromirrorDesign&)) {
    TorsionalMicromirrorDesign design;
    change(design);
    return test::ErrorField(&TorsionalMicromirror, design);
  };
  EXPECT_EQ(field([](TorsionalMicromirrorDesign&) {}), "built");
  EXPECT_EQ(field([](TorsionalMicromirrorDesign& d) { d.beam_length = 0; }),
            "structure.beam_length");
  EXPECT_EQ(field([](TorsionalMicromirrorDesign& d) { d.beam_width = -3e-6; }),
            "structure.beam_width");
  EXPECT_EQ(field([](TorsionalMicromirrorDesign& d) { d.plate_width = 0; }),
            "structure.plate_width");
  EXPECT_EQ(field([](TorsionalMicromirrorDesign& d) { d.plate_length = 0; }),
            "structure.plate_length");
  // A beam wider than the plate's side it meets.
  EXPECT_EQ(field([](TorsionalMicromirrorDesign& d) { d.beam_width = 200e-6; }),
            "structure.beam_width");
}

}  // namespace
}  // namespace cosmems
