// The serpentine-suspended plate's generator: pressed toward the substrate, the springs carry the
// load by out-of-plane bending and Saint-Venant torsion alone, which the frame's members model
// exactly, so the plate sinks by the closed form (Castigliano, SerpentineDesign::Stiffness) and
// by the oracle to round-off (1e-9 of the motion), whatever the design.
#include <gtest/gtest.h>

#include "device_checks.hpp"

namespace cosmems {
namespace {

constexpr double kSerpentinePress = -1e-6;  // N along y at the plate's centre

double SerpentineSink(const SerpentineDesign& design) {
  return test::SolveBodyMotion(Serpentine(design), 0, {0, kSerpentinePress, 0})[1];
}

TEST(SerpentineTest, ThePlateSinksByTheClosedFormAndTheOracles) {
  SerpentineDesign design;
  design.elements = 2;
  const StructureDescription s = Serpentine(design);
  EXPECT_EQ(s.members.size(), 4u * (2u * 4u + 1u));
  const test::BodyMotion sunk = test::SolveBodyMotion(s, 0, {0, kSerpentinePress, 0});
  const test::BodyMotion oracle = test::OracleBodyMotion(s, 0, {0, kSerpentinePress, 0});
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(sunk[k], oracle[k], 1e-9 * -sunk[1]);
  for (int k = 3; k < 6; ++k) EXPECT_NEAR(sunk[k], 0.0, 1e-9 * -sunk[1] / design.plate_width);
  EXPECT_NEAR(kSerpentinePress / sunk[1], design.Stiffness(), 1e-9 * design.Stiffness());
}

// An odd and an even number of turns (the last connector on either side), one turn, another
// section (torsion and bending in another ratio) and another Poisson's ratio (G alone changes).
TEST(SerpentineTest, TheClosedFormHoldsForEveryDesign) {
  SerpentineDesign design;
  design.elements = 1;
  for (int turns : {1, 2, 5, 8}) {
    design.turns = turns;
    EXPECT_NEAR(kSerpentinePress / SerpentineSink(design), design.Stiffness(),
                1e-9 * design.Stiffness())
        << turns << " turns";
  }
  design.span_length = 80e-6;
  design.connector_length = 6e-6;
  design.beam_width = 4e-6;
  design.material.poisson_ratio = 0.3;
  EXPECT_NEAR(kSerpentinePress / SerpentineSink(design), design.Stiffness(),
              1e-9 * design.Stiffness());
}

// At order 0 the same matrices as the oracle's: measured within 1.3e-11, the round-off of the
// solves, which grows with the mesh here (its 5 um connector elements are the shortest of the
// devices': 6e-12 at one element per segment, 6e-11 at four).
TEST(SerpentineTest, ItsModesAreTheOracles) {
  SerpentineDesign design;
  design.elements = 2;
  test::ExpectModesMatchOracle(Serpentine(design), 6, 1e-10);
}

TEST(SerpentineTest, ParameterErrorsNameTheirKey) {
  auto field = [](void (*change)(SerpentineDesign&)) {
    SerpentineDesign design;
    change(design);
    return test::ErrorField(&Serpentine, design);
  };
  EXPECT_EQ(field([](SerpentineDesign&) {}), "built");
  EXPECT_EQ(field([](SerpentineDesign& d) { d.span_length = 0; }), "structure.span_length");
  EXPECT_EQ(field([](SerpentineDesign& d) { d.connector_length = -1e-6; }),
            "structure.connector_length");
  EXPECT_EQ(field([](SerpentineDesign& d) { d.beam_width = 0; }), "structure.beam_width");
  EXPECT_EQ(field([](SerpentineDesign& d) { d.plate_width = 0; }), "structure.plate_width");
  EXPECT_EQ(field([](SerpentineDesign& d) { d.turns = 0; }), "structure.turns");
  // Spans a connector apart that is no wider than a span touch; a plate narrower than two
  // springs' widths cannot hold them apart.
  EXPECT_EQ(field([](SerpentineDesign& d) { d.connector_length = 2e-6; }),
            "structure.connector_length");
  EXPECT_EQ(field([](SerpentineDesign& d) { d.plate_length = 3e-6; }), "structure.plate_length");
}

}  // namespace
}  // namespace cosmems
