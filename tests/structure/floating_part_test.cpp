// FindFloatingPart against the model's own stiffness: a part it calls floating has a rigid
// motion that the assembled K (FrameModel) maps to zero, and a structure it calls held has a K
// that factors.
#include "cosmems/structure/floating_part.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <optional>

#include "test_frames.hpp"

namespace cosmems {
namespace {

using test::AddBeam;
using test::AddBody;
using test::AddNode;

constexpr double kSpan = 100e-6;

// The reduced dofs of the rigid motion u = t + w x (x - centre) of the part's carriers (its
// nodes, its members' interior nodes, its bodies; internal units), the rest at rest, the centre
// the mean of the part's nodes as FindFloatingPart takes it.
Eigen::VectorXd RigidMotionDofs(const FrameModel& model, const FloatingPart& part) {
  const StructureDescription& s = model.description();
  const FrameMesh& mesh = model.mesh();
  std::vector<char> moves(mesh.carriers.size(), 0);
  for (int n : part.nodes) moves[mesh.nodes[n].carrier] = 1;
  for (const FrameMesh::Element& e : mesh.elements) {
    if (std::find(part.members.begin(), part.members.end(), e.member) == part.members.end())
      continue;
    moves[mesh.nodes[e.from].carrier] = moves[mesh.nodes[e.to].carrier] = 1;
  }
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int n : part.nodes) centre += s.nodes[n].position;
  centre /= static_cast<double>(part.nodes.size());
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const std::vector<FrameMesh::Carrier>& carriers = mesh.carriers;
  for (std::size_t c = 0; c < carriers.size(); ++c) {
    if (!moves[c]) continue;
    const Eigen::Vector3d u =
        (part.translation + part.rotation.cross(carriers[c].position - centre)) /
        model.units().length;
    for (int k = 0; k < 6; ++k) {
      const int dof = model.CarrierDof(static_cast<int>(c), k);
      if (dof >= 0) d[dof] = k < 3 ? u[k] : part.rotation[k - 3];
    }
  }
  return d;
}

// A floating part's motion is a null vector of K (to round-off against K's scale), and no
// anchored dof moves in it.
void ExpectFloatsBy(const StructureDescription& s, const FloatingPart& part) {
  const FrameModel model(s);
  const Eigen::MatrixXd k = model.Stiffness().ToDense();
  const Eigen::VectorXd d = RigidMotionDofs(model, part);
  ASSERT_GT(d.norm(), 0.0);
  EXPECT_LT((k * d).norm(), 1e-9 * k.norm() * d.norm());
}

bool Factors(const StructureDescription& s) {
  const FrameModel model(s);
  const Eigen::LLT<Eigen::MatrixXd> llt(model.Stiffness().ToDense());
  return llt.info() == Eigen::Success;
}

// An L of two members in the plane, from node 0 along x, then along z.
StructureDescription LShape(Support root, Support corner, Support end) {
  StructureDescription s;
  AddNode(s, "root", {0, 0, 0}, root);
  AddNode(s, "corner", {kSpan, 0, 0}, corner);
  AddNode(s, "end", {kSpan, 0, kSpan}, end);
  AddBeam(s, 0, 1, 3);
  AddBeam(s, 1, 2, 3);
  return s;
}

TEST(FloatingPartTest, AClampedStructureIsHeld) {
  const StructureDescription s = LShape(Support::kClamped, Support::kFree, Support::kFree);
  EXPECT_FALSE(FindFloatingPart(s).has_value());
  EXPECT_TRUE(Factors(s));
}

TEST(FloatingPartTest, AStructureWithoutAnchorsFloatsWhole) {
  const StructureDescription s = LShape(Support::kFree, Support::kFree, Support::kFree);
  const std::optional<FloatingPart> part = FindFloatingPart(s);
  ASSERT_TRUE(part.has_value());
  EXPECT_EQ(part->nodes, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(part->members, (std::vector<int>{0, 1}));
  EXPECT_TRUE(part->anchors.empty());
  ExpectFloatsBy(s, *part);
}

// A beam pinned at both ends turns about the line through the pins unless one pin holds the twist
// (a pinned support fixes rx, the twist of a member along x): along z nothing holds it.
TEST(FloatingPartTest, PinsOnALineLeaveTheTurnAboutIt) {
  StructureDescription s;
  AddNode(s, "a", {0, 0, 0}, Support::kPinned);
  AddNode(s, "b", {0, 0, kSpan}, Support::kPinned);
  AddBeam(s, 0, 1, 4);
  const std::optional<FloatingPart> part = FindFloatingPart(s);
  ASSERT_TRUE(part.has_value());
  EXPECT_EQ(part->anchors, (std::vector<int>{0, 1}));
  EXPECT_TRUE(part->translation.isZero(0.0)) << part->translation.transpose();
  EXPECT_NEAR(std::abs(part->rotation.normalized().z()), 1.0, 1e-12);
  ExpectFloatsBy(s, *part);
  EXPECT_FALSE(Factors(s));

  StructureDescription along_x;
  AddNode(along_x, "a", {0, 0, 0}, Support::kPinned);
  AddNode(along_x, "b", {kSpan, 0, 0}, Support::kPinned);
  AddBeam(along_x, 0, 1, 4);
  EXPECT_FALSE(FindFloatingPart(along_x).has_value());
  EXPECT_TRUE(Factors(along_x));
}

// Anchors that fix only the out-of-plane displacement leave a plate free to slide in its plane,
// however many there are.
TEST(FloatingPartTest, OutOfPlaneAnchorsLeaveThePlaneFree) {
  StructureDescription s;
  std::vector<int> corners;
  for (int i = 0; i < 4; ++i) {
    const double x = (i % 2 ? 1.0 : -1.0) * kSpan, z = (i / 2 ? 1.0 : -1.0) * kSpan;
    const int anchor = AddNode(s, "a" + std::to_string(i), {2 * x, 0, z});
    s.nodes[anchor].anchor = AnchorMask{false, true, false, false, false, false};
    corners.push_back(AddNode(s, "c" + std::to_string(i), {x, 0, z}));
    AddBeam(s, anchor, corners.back(), 2);
  }
  AddBody(s, "plate", {0, 0, 0}, {2 * kSpan, 2e-6, 2 * kSpan}, corners);
  const std::optional<FloatingPart> part = FindFloatingPart(s);
  ASSERT_TRUE(part.has_value());
  EXPECT_EQ(part->nodes.size(), 8u);
  EXPECT_EQ(part->bodies, (std::vector<int>{0}));
  EXPECT_EQ(part->anchors, (std::vector<int>{0, 2, 4, 6}));
  // A translation along x is free, and the first the search names.
  EXPECT_TRUE(part->rotation.isZero(0.0)) << part->rotation.transpose();
  EXPECT_EQ(part->translation.normalized(), Eigen::Vector3d::UnitX());
  ExpectFloatsBy(s, *part);

  for (StructureNode& node : s.nodes) {
    if (node.anchor[1]) node.anchor = AnchorOf(Support::kClamped);
  }
  EXPECT_FALSE(FindFloatingPart(s).has_value());
  EXPECT_TRUE(Factors(s));
}

// A held structure beside one that nothing holds: the loose part is named alone, and a node on
// its own is a part of its own.
TEST(FloatingPartTest, NamesTheLoosePartBesideAHeldOne) {
  StructureDescription s = LShape(Support::kClamped, Support::kFree, Support::kFree);
  AddNode(s, "x", {0, kSpan, 0});
  AddNode(s, "y", {kSpan, kSpan, 0});
  AddBeam(s, 3, 4, 2);
  std::optional<FloatingPart> part = FindFloatingPart(s);
  ASSERT_TRUE(part.has_value());
  EXPECT_EQ(part->nodes, (std::vector<int>{3, 4}));
  EXPECT_EQ(part->members, (std::vector<int>{2}));
  ExpectFloatsBy(s, *part);

  StructureDescription lone = LShape(Support::kClamped, Support::kFree, Support::kFree);
  AddNode(lone, "lone", {0, kSpan, 0}, Support::kPinned);
  part = FindFloatingPart(lone);
  ASSERT_TRUE(part.has_value());
  EXPECT_EQ(part->nodes, (std::vector<int>{3}));
  EXPECT_TRUE(part->members.empty());
  ExpectFloatsBy(lone, *part);
  lone.nodes[3].anchor = AnchorOf(Support::kClamped);
  EXPECT_FALSE(FindFloatingPart(lone).has_value());
}

// The generators' devices are all held.
TEST(FloatingPartTest, TheParametricDevicesAreHeld) {
  EXPECT_FALSE(FindFloatingPart(test::FoldedFlexure(100e-6, 2)).has_value());
  EXPECT_FALSE(FindFloatingPart(CrabLeg(CrabLegDesign{})).has_value());
  EXPECT_FALSE(FindFloatingPart(Serpentine(SerpentineDesign{})).has_value());
  EXPECT_FALSE(FindFloatingPart(TorsionalMicromirror(TorsionalMicromirrorDesign{})).has_value());
  EXPECT_FALSE(FindFloatingPart(Accelerometer(AccelerometerDesign{})).has_value());
}

}  // namespace
}  // namespace cosmems
