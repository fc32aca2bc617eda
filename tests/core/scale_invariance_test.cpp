// The same physical problem at 100 nm and at 1 mm scale gives the same relative answers, on the
// beam's one-member netlist as every front end builds it. Geometrically similar cantilevers and
// bridges of one material: with forces scaled as s^2, deflections scale as s, stresses stay,
// frequencies scale as 1/s. Internal units make the internal problems identical, so the answers
// agree to round-off; 1e-9 relative is the requirement.
#include <gtest/gtest.h>

#include "cosmems/analysis/frame_modal_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/structure/straight_beam.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

struct ScaledAnswers {
  double tip_over_length;
  double slope;
  double stress;
  double frequency_times_length;
};

ScaledAnswers SolveAtScale(double length, StructureKind kind, bool planar) {
  StraightBeamDesign d;
  d.bridge = kind == StructureKind::kBridge;
  d.length = length;
  d.material = test::Silicon();
  d.section = RectangularSection{0.1 * length, 0.01 * length};
  d.elements = 20;
  d.series_order = 1;
  d.planar = planar;
  const FrameModel model(StraightBeam(d));
  // The cantilever's tip (node 1) or the bridge's midspan.
  const double at = d.bridge ? 0.5 : 1.0;
  FrameLoadCase loads;
  loads.points.push_back(
      {-1, -1, Eigen::Vector3d(0, -1e3 * length * length, 0), Eigen::Vector3d::Zero(), 0, at});
  const FrameStaticSolution solution = SolveFrameStatic(model, loads);
  EXPECT_EQ(solution.status, Status::kOk);
  const double unit = model.units().length;
  ModalOptions options;
  options.count = 3;
  const ModalResult modes = SolveModal(model, options);
  return {model.MemberMotion(solution.displacement, 0, at)[1] * unit / length,
          model.MemberMotion(solution.displacement, 0, 0.25)[5], solution.max_stress_pa,
          modes.modes[2].frequency_hz * length};
}

void ExpectScaleInvariant(StructureKind kind, bool planar) {
  const ScaledAnswers nano = SolveAtScale(100e-9, kind, planar);
  const ScaledAnswers milli = SolveAtScale(1e-3, kind, planar);
  constexpr double kTolerance = 1e-9;
  EXPECT_NEAR(nano.tip_over_length, milli.tip_over_length,
              kTolerance * std::abs(milli.tip_over_length));
  EXPECT_NEAR(nano.slope, milli.slope, kTolerance * std::abs(milli.slope));
  EXPECT_NEAR(nano.stress, milli.stress, kTolerance * milli.stress);
  EXPECT_NEAR(nano.frequency_times_length, milli.frequency_times_length,
              kTolerance * milli.frequency_times_length);
}

TEST(ScaleInvarianceTest, PlanarCantilever) {
  ExpectScaleInvariant(StructureKind::kCantilever, true);
}
TEST(ScaleInvarianceTest, SpatialCantilever) {
  ExpectScaleInvariant(StructureKind::kCantilever, false);
}
TEST(ScaleInvarianceTest, SpatialBridge) { ExpectScaleInvariant(StructureKind::kBridge, false); }

}  // namespace
}  // namespace cosmems
