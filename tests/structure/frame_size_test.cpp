// FrameSizeOf against the model it sizes: the unknowns FrameModel numbers, and a band no narrower
// than the one it assembles, linear or stretching.
#include "cosmems/structure/frame_size.hpp"

#include <gtest/gtest.h>

#include "test_frames.hpp"

namespace cosmems {
namespace {

void ExpectSizesTheModel(const StructureDescription& s) {
  const FrameSize size = FrameSizeOf(s);
  std::int64_t elements = 0;
  for (const StructureMember& m : s.members) elements += m.elements;
  EXPECT_EQ(size.elements, elements);
  EXPECT_EQ(FrameElementCount(s), elements);
  for (const FrameCouplings couplings :
       {FrameCouplings::kLinear, FrameCouplings::kStretching, FrameCouplings::kTwist,
        FrameCouplings::kStretching | FrameCouplings::kTwist}) {
    const FrameModel model(s, couplings);
    EXPECT_EQ(size.unknowns, model.FreeDofCount());
    EXPECT_GE(size.bandwidth, model.Stiffness().bandwidth());
  }
}

TEST(FrameSizeTest, SizesTheParametricDevices) {
  ExpectSizesTheModel(test::FoldedFlexure(100e-6, 1));
  ExpectSizesTheModel(test::FoldedFlexure(100e-6, 7));
  // The bound is the band of the benchmarks' folded flexure when its members stretch (23; 11
  // linear): one group holds all six directions there.
  const StructureDescription benchmark = test::FoldedFlexure(100e-6, 125);
  EXPECT_EQ(FrameSizeOf(benchmark).bandwidth,
            FrameModel(benchmark, FrameCouplings::kStretching).Stiffness().bandwidth());
  // A probe's twist joins the bending across the thickness to the torsion, which the planar
  // device's out-of-plane group holds together already: its band does not grow.
  EXPECT_EQ(FrameModel(benchmark, FrameCouplings::kTwist).Stiffness().bandwidth(),
            FrameModel(benchmark).Stiffness().bandwidth());
  CrabLegDesign crab_leg;
  crab_leg.elements = 3;
  ExpectSizesTheModel(CrabLeg(crab_leg));
  SerpentineDesign serpentine;
  serpentine.elements = 2;
  ExpectSizesTheModel(Serpentine(serpentine));
  ExpectSizesTheModel(TorsionalMicromirror(TorsionalMicromirrorDesign{}));
  ExpectSizesTheModel(Accelerometer(AccelerometerDesign{}));
}

// A grid of members, whose band grows with its width however it is numbered, with partial
// anchors along one edge and a body across two nodes.
TEST(FrameSizeTest, SizesAGridWithPartialAnchorsAndABody) {
  constexpr int kSide = 5;
  constexpr double kPitch = 50e-6;
  StructureDescription s;
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const Support support =
          i == 0 ? (j % 2 ? Support::kPinned : Support::kClamped) : Support::kFree;
      test::AddNode(s, "n" + std::to_string(i) + "_" + std::to_string(j),
                    {i * kPitch, 0.0, j * kPitch}, support);
    }
  }
  for (int i = 0; i < kSide; ++i) {
    for (int j = 0; j < kSide; ++j) {
      const int n = i * kSide + j;
      if (i + 1 < kSide) test::AddBeam(s, n, n + kSide, 2);
      if (j + 1 < kSide) test::AddBeam(s, n, n + 1, 3);
    }
  }
  const int last = kSide * kSide - 1;
  test::AddBody(s, "tab", {(kSide - 1) * kPitch, 0.0, (kSide - 1.5) * kPitch},
                {10e-6, 2e-6, kPitch + 10e-6}, {last - 1, last});
  ExpectSizesTheModel(s);
}

}  // namespace
}  // namespace cosmems
