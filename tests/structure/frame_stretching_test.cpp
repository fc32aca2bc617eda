// Members that stretch as they bend (FrameStretchingForce): its force and tangent against
// finite differences of an energy written here from Hermite slopes, a netlist bridge against the
// exact stretched bridge (tests/beam/stretched_bridge.hpp) and the beam's StretchingForce, and
// the stiffening of a shuttle held between two beams against the Galerkin cubic, beside a folded
// flexure, whose trusses let its beams slide and which stays linear.
#include <gtest/gtest.h>

#include <cmath>

#include "beam/stretched_bridge.hpp"
#include "force_differences.hpp"
#include "test_beams.hpp"
#include "test_frames.hpp"

namespace cosmems {
namespace {

// The energy the linear elements leave out, EA l (2 e0 s + s^2) / 2 per element, with
// s = 1/(2l) int (v'^2 + w'^2) dx from the cubic Hermite slopes by 3-point Gauss (exact for the
// quartic integrand), in the model's internal units.
double StretchingEnergy(const FrameModel& model, const Eigen::VectorXd& d) {
  const double xi[3] = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)};
  const double weight[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  double energy = 0.0;
  for (int e = 0; e < model.ElementCount(); ++e) {
    const ElementProperties& p = model.elements()[e].properties();
    const double l = p.length, ea = p.young_modulus * p.area;
    const FrameModel::ElementVector q = model.LocalDisplacement(d, e);
    double integral = 0.0;
    for (int g = 0; g < 3; ++g) {
      const double x = xi[g];
      const double n1 = (-6 * x + 6 * x * x) / l, n2 = 1 - 4 * x + 3 * x * x;
      const double n3 = (6 * x - 6 * x * x) / l, n4 = -2 * x + 3 * x * x;
      const double v = n1 * q[1] + n2 * q[5] + n3 * q[7] + n4 * q[11];  // theta_z = v'
      const double w = n1 * q[2] - n2 * q[4] + n3 * q[8] - n4 * q[10];  // theta_y = -w'
      integral += weight[g] * l * (v * v + w * w);
    }
    const double s = integral / (2 * l), e0 = (q[6] - q[0]) / l;
    energy += 0.5 * ea * l * (2 * e0 * s + s * s);
  }
  return energy;
}

TEST(FrameStretchingTest, ForceAndTangentMatchFiniteDifferencesOfTheEnergy) {
  // An L-frame turned out of every plane, so that every direction couples, with a body.
  StructureDescription s;
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const double l = 100e-6;
  test::AddNode(s, "anchor", {0, 0, 0}, Support::kClamped);
  test::AddNode(s, "corner", turn * Eigen::Vector3d(l, 0, 0));
  test::AddNode(s, "tip", turn * Eigen::Vector3d(l, 0, 0.6 * l));
  test::AddBeam(s, 0, 1, 3, test::SquareSection(), turn.col(1));
  test::AddBeam(s, 1, 2, 2, RectangularSection{3e-6, 2e-6}, turn.col(1));
  test::AddBody(s, "block", turn * Eigen::Vector3d(l, 0, 0.7 * l), {20e-6, 2e-6, 20e-6}, {2});
  const FrameModel model(s, FrameCouplings::kStretching);
  FrameStretchingForce force(model);
  Eigen::VectorXd d = 0.02 * Eigen::VectorXd::Random(model.FreeDofCount());  // a fiftieth of l
  // Steps of 1e-6 of the displacement: central differences err by h^2 times the third
  // derivative, 1e-12 of the force; the energy's round-off over h leaves about 1e-9.
  test::ExpectForceAndTangentMatchDifferences(
      force, d, model.Stiffness().bandwidth(),
      [&](const Eigen::VectorXd& x) { return StretchingEnergy(model, x); }, 1e-8, 1e-6);
  EXPECT_THROW(FrameStretchingForce{FrameModel(s)}, std::invalid_argument);
}

// A bridge as a netlist of two members meeting at mid-span, loaded toward the substrate by
// q = -100 N/m, five thicknesses deep: the beam's exact stretched bridge within 1e-4 (the
// clamps' boundary layers at 40 elements, as for the beam), and the beam's own StretchingForce
// at the same mesh to the Newton tolerance: in statics the elements' axial nodes settle where
// the tension is uniform, which the beam's force assumes.
TEST(FrameStretchingTest, ANetlistBridgeStretchesAsTheBeamAndTheExactBridge) {
  const double length = test::kReferenceLength, q = -100.0;
  StructureDescription s;
  test::AddNode(s, "left", {0, 0, 0}, Support::kClamped);
  test::AddNode(s, "mid", {length / 2, 0, 0});
  test::AddNode(s, "right", {length, 0, 0}, Support::kClamped);
  for (int m = 0; m < 2; ++m) {
    s.members.push_back({m, m + 1, test::Silicon(), test::ReferenceSection(), 20, {0, 1, 0}});
  }
  const FrameModel model(s, FrameCouplings::kStretching);
  FrameStretchingForce stretching(model);
  FrameLoadCase loads;
  loads.distributed = Eigen::Vector3d(0, q, 0);
  const FrameStaticSolution frame = SolveFrameNonlinearStatic(model, {&stretching}, loads);
  ASSERT_EQ(frame.status, Status::kOk);

  const double ea = test::Silicon().young_modulus * test::ReferenceSection().Area();
  const test::StretchedBridge exact = test::SolveStretchedBridge(length, test::Eiz(), ea, q, 0.0);
  const double midspan = frame.nodes[1][1];
  EXPECT_NEAR(midspan, exact.midspan, 1e-4 * std::abs(exact.midspan));
  EXPECT_NEAR(frame.axial_force_n, exact.tension, 1e-4 * exact.tension);
  EXPECT_GT(std::abs(midspan), 3 * test::kReferenceThickness);

  const BeamModel<3> beam(MakeStructure(StructureKind::kBridge, length, test::Silicon(),
                                        test::ReferenceSection(), 40, 1));
  StretchingForce<3> condensed(beam);
  LoadCase uniform;
  uniform.distributed = Eigen::Vector3d(0, q, 0);
  const NonlinearStaticSolution chain = SolveNonlinearStatic(beam, condensed, uniform);
  ASSERT_EQ(chain.status, Status::kOk);
  const double beam_midspan = BeamField<3>(beam, chain.displacement).At(length / 2)[1];
  EXPECT_NEAR(midspan, beam_midspan, 1e-8 * std::abs(beam_midspan));
  // The reactions carry the load and the tension pulls the clamps inward.
  double held = 0.0;
  for (const FrameReaction& r : frame.reactions) held += r.force.y();
  EXPECT_NEAR(held, -q * length, 1e-9 * std::abs(q) * length);
  EXPECT_NEAR(frame.reactions[0].force.x(), -exact.tension, 1e-4 * exact.tension);
}

// A shuttle held between two beams along z, each clamped at its anchor, pulled along x: the
// beams lengthen and their tension stiffens it. The Galerkin model in the beams' linear
// (clamped-guided) shape gives F = 24 EI/L^3 x + (36/25) EA/L^3 x^3, whose cubic term is
// exact to first order in the shift; at a 2 % shift the next order is of the shift's order at
// most (measured 6.8e-4 of it; 1 % asserted). The folded flexure pulled as far stays linear to
// round-off (measured 2e-13): its trusses slide along the beams, so no member's ends are held
// apart.
TEST(FrameStretchingTest, AShuttleBetweenTwoBeamsStiffensAndAFoldedFlexureDoesNot) {
  const double l = 100e-6, half = 20e-6;
  StructureDescription s;
  test::AddNode(s, "low", {0, 0, -half - l}, Support::kClamped);
  test::AddNode(s, "low_joint", {0, 0, -half});
  test::AddNode(s, "high_joint", {0, 0, half});
  test::AddNode(s, "high", {0, 0, half + l}, Support::kClamped);
  test::AddBeam(s, 0, 1, 10);
  test::AddBeam(s, 2, 3, 10);
  test::AddBody(s, "shuttle", {0, 0, 0}, {40e-6, 2e-6, 2 * half}, {1, 2});
  const double ei = test::Poly().young_modulus * test::SquareSection().SecondMomentY();
  const double ea = test::Poly().young_modulus * test::SquareSection().Area();
  const double k1 = 24 * ei / (l * l * l), k3 = 36.0 / 25 * ea / (l * l * l);
  const double x = std::sqrt(0.02 * k1 / k3);  // where the cubic adds 2 %
  const double shift = k3 * x * x / k1;
  auto pulled = [&](const StructureDescription& structure, int body, double force) {
    const FrameModel model(structure, FrameCouplings::kStretching);
    FrameStretchingForce stretching(model);
    FrameLoadCase pull;
    pull.points.push_back({-1, body, {force, 0, 0}, {0, 0, 0}});
    const FrameStaticSolution solution = SolveFrameNonlinearStatic(model, {&stretching}, pull);
    EXPECT_EQ(solution.status, Status::kOk);
    return solution.bodies[body][0];
  };
  const double force = k1 * x + k3 * x * x * x;
  const double moved = pulled(s, 0, force);
  const double stiffening = force / moved / k1 - 1.0;
  EXPECT_NEAR(stiffening, shift, 0.01 * shift);

  // The folded flexure (k = 24 E I / L^3 too) pulled as far.
  const StructureDescription flexure = test::FoldedFlexure(l, 10);
  const double k_flexure = FoldedFlexureDesign{}.Stiffness();
  const double folded = x / pulled(flexure, 2, k_flexure * x) - 1.0;
  EXPECT_LT(std::abs(folded), 1e-9);
}

}  // namespace
}  // namespace cosmems
