// The same physical problem at 100 nm and at 1 mm scale gives the same relative answers.
// Geometrically similar cantilevers of one material: with forces scaled as s^2, deflections
// scale as s, stresses stay, frequencies scale as 1/s. Internal units make the internal
// problems identical, so the answers agree to round-off; 1e-9 relative is the requirement.
#include <gtest/gtest.h>

#include "test_beams.hpp"

namespace cosmems {
namespace {

struct Answers {
  double tip_over_length;
  double slope;
  double stress;
  double frequency_times_length;
};

template <int Dim>
Answers Solve(double length, StructureKind kind) {
  const RectangularSection s{0.1 * length, 0.01 * length};
  const BeamModel<Dim> model(MakeStructure(kind, length, test::Silicon(), s, 20, 1));
  LoadCase loads;
  const double x = kind == StructureKind::kCantilever ? length : 0.5 * length;
  loads.points.push_back(
      {x, Eigen::Vector3d(0, -1e3 * length * length, 0), Eigen::Vector3d::Zero()});
  const StaticSolution solution = SolveStatic(model, loads);
  const BeamField<Dim> field(model, solution.displacement);
  ModalOptions options;
  options.count = 3;
  const ModalResult modes = SolveModal(model, options);
  return {field.At(x)[1] / length, field.At(0.25 * length)[5], field.MaxStress(),
          modes.modes[2].frequency_hz * length};
}

template <int Dim>
void ExpectScaleInvariant(StructureKind kind) {
  const Answers nano = Solve<Dim>(100e-9, kind);
  const Answers milli = Solve<Dim>(1e-3, kind);
  constexpr double kTolerance = 1e-9;
  EXPECT_NEAR(nano.tip_over_length, milli.tip_over_length,
              kTolerance * std::abs(milli.tip_over_length));
  EXPECT_NEAR(nano.slope, milli.slope, kTolerance * std::abs(milli.slope));
  EXPECT_NEAR(nano.stress, milli.stress, kTolerance * milli.stress);
  EXPECT_NEAR(nano.frequency_times_length, milli.frequency_times_length,
              kTolerance * milli.frequency_times_length);
}

TEST(ScaleInvarianceTest, PlanarCantilever) { ExpectScaleInvariant<2>(StructureKind::kCantilever); }
TEST(ScaleInvarianceTest, SpatialCantilever) {
  ExpectScaleInvariant<3>(StructureKind::kCantilever);
}
TEST(ScaleInvarianceTest, SpatialBridge) { ExpectScaleInvariant<3>(StructureKind::kBridge); }

}  // namespace
}  // namespace cosmems
