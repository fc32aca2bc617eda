// Frame elements and assembled matrices: rigid-body motions (which fix every sign convention),
// the classical 3-D frame entries, total mass and rotary inertia, symmetry and definiteness.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <vector>

#include "test_beams.hpp"

namespace cosmems {
namespace {

ElementProperties UnitProperties() {
  ElementProperties p;
  p.length = 0.7;
  p.young_modulus = 3.0;
  p.shear_modulus = 1.2;
  p.density = 2.0;
  p.area = 0.5;
  p.second_moment_y = 0.11;
  p.second_moment_z = 0.05;
  p.torsion_constant = 0.09;
  p.polar_moment = 0.16;
  return p;
}

// The six rigid motions of a 3-D element with nodes at x = 0 and x = l, as nodal vectors.
Eigen::Matrix<double, 12, 6> RigidMotions(double l) {
  Eigen::Matrix<double, 12, 6> r = Eigen::Matrix<double, 12, 6>::Zero();
  for (int node = 0; node < 2; ++node) {
    const double x = node * l;
    const int o = 6 * node;
    r(o + 0, 0) = 1;   // translation x
    r(o + 1, 1) = 1;   // translation y
    r(o + 2, 2) = 1;   // translation z
    r(o + 3, 3) = 1;   // rotation about x
    r(o + 2, 4) = -x;  // rotation about y: uz = -x theta, ry = theta
    r(o + 4, 4) = 1;
    r(o + 1, 5) = x;  // rotation about z: uy = x theta, rz = theta
    r(o + 5, 5) = 1;
  }
  return r;
}

TEST(FrameElementTest, RigidMotionsStoreNoEnergyAtAnyOrder) {
  const ElementProperties p = UnitProperties();
  const FrameElement<3> element(p);
  for (int order : {0, 1, 3}) {
    const FrameBases bases(order);
    const auto k = element.Stiffness(bases);
    EXPECT_LT((k * RigidMotions(p.length)).norm(), 1e-13 * k.norm()) << "order " << order;
  }
}

TEST(FrameElementTest, StiffnessHasTheClassicalFrameEntries) {
  const ElementProperties p = UnitProperties();
  const auto k = FrameElement<3>(p).Stiffness(FrameBases(1));
  const double l = p.length, e = p.young_modulus;
  EXPECT_NEAR(k(0, 0), e * p.area / l, 1e-14);
  EXPECT_NEAR(k(1, 1), 12 * e * p.second_moment_z / (l * l * l), 1e-13);
  EXPECT_NEAR(k(1, 5), 6 * e * p.second_moment_z / (l * l), 1e-13);
  EXPECT_NEAR(k(2, 2), 12 * e * p.second_moment_y / (l * l * l), 1e-13);
  EXPECT_NEAR(k(2, 4), -6 * e * p.second_moment_y / (l * l), 1e-13);
  EXPECT_NEAR(k(3, 3), p.shear_modulus * p.torsion_constant / l, 1e-14);
  EXPECT_NEAR(k(4, 4), 4 * e * p.second_moment_y / l, 1e-13);
  EXPECT_NEAR(k(5, 11), 2 * e * p.second_moment_z / l, 1e-13);
}

TEST(FrameElementTest, ConsistentMassCarriesTheElementMassAndRotaryInertia) {
  const ElementProperties p = UnitProperties();
  const auto m = FrameElement<3>(p).Mass(FrameBases(0), 0);
  const auto r = RigidMotions(p.length);
  const double mass = p.density * p.area * p.length;
  for (int t = 0; t < 3; ++t) EXPECT_NEAR(r.col(t).dot(m * r.col(t)), mass, 1e-14);
  EXPECT_NEAR(r.col(3).dot(m * r.col(3)), p.density * p.polar_moment * p.length, 1e-14);
  // Rotation about z through x = 0 moves the axis as uy = x: inertia rho A l^3 / 3 (the
  // Euler-Bernoulli element carries no rotary inertia of the section).
  EXPECT_NEAR(r.col(5).dot(m * r.col(5)), mass * p.length * p.length / 3, 1e-14);
}

TEST(FrameElementTest, PlanarElementIsTheInPlaneBlockOfTheSpatialOne) {
  const ElementProperties p = UnitProperties();
  const FrameBases bases(2);
  const int map[6] = {0, 1, 5, 6, 7, 11};  // ux, uy, rz of both nodes
  for (int term = -1; term <= 2; ++term) {
    const auto planar =
        term < 0 ? FrameElement<2>(p).Stiffness(bases) : FrameElement<2>(p).Mass(bases, term);
    const auto spatial =
        term < 0 ? FrameElement<3>(p).Stiffness(bases) : FrameElement<3>(p).Mass(bases, term);
    for (int a = 0; a < 6; ++a) {
      for (int b = 0; b < 6; ++b) EXPECT_DOUBLE_EQ(planar(a, b), spatial(map[a], map[b]));
    }
  }
}

TEST(BeamModelTest, AssembledMatricesAreSymmetricAndPositiveDefinite) {
  for (auto kind : {StructureKind::kCantilever, StructureKind::kBridge}) {
    const BeamModel<3> model(MakeStructure(kind, test::kReferenceLength, test::Silicon(),
                                           test::ReferenceSection(), 7, 2));
    const Eigen::MatrixXd k = model.Stiffness().ToDense();
    const Eigen::MatrixXd m = model.Mass(0).ToDense();
    EXPECT_EQ(model.FreeDofCount(), kind == StructureKind::kBridge ? 36 : 42);
    EXPECT_EQ(model.Stiffness().bandwidth(), 3);  // one bending field: (u, r) at two nodes
    EXPECT_EQ((k - k.transpose()).norm(), 0.0);
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(k).info(), Eigen::Success);
    EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(m).info(), Eigen::Success);
    for (int j = 1; j <= 2; ++j) {
      const Eigen::MatrixXd mj = model.Mass(j).ToDense();
      EXPECT_EQ((mj - mj.transpose()).norm(), 0.0);
    }
  }
}

// Field-by-field numbering only permutes the free degrees of freedom: every entry of K and of
// each M_2j must equal the node-by-node entry of the same pair of nodal dofs, bit for bit, and
// nothing may fall outside the narrower band.
template <int Dim>
void ExpectSameMatricesPermuted(const BeamDescription& beam, int node_band, int field_band) {
  const BeamModel<Dim> by_field(beam, DofNumbering::kByField);
  const BeamModel<Dim> by_node(beam, DofNumbering::kByNode);
  EXPECT_EQ(by_field.Stiffness().bandwidth(), field_band);
  EXPECT_EQ(by_node.Stiffness().bandwidth(), node_band);
  ASSERT_EQ(by_field.FreeDofCount(), by_node.FreeDofCount());
  std::vector<int> field_of_node(by_node.FreeDofCount(), -1);
  for (int node = 0; node < by_node.NodeCount(); ++node) {
    for (int d = 0; d < 6; ++d) {
      const int r = by_node.dofs().Reduced(node, static_cast<NodalDof>(d));
      if (r >= 0) field_of_node[r] = by_field.dofs().Reduced(node, static_cast<NodalDof>(d));
    }
  }
  for (int term = -1; term <= beam.series_order; ++term) {
    const Eigen::MatrixXd a = (term < 0 ? by_node.Stiffness() : by_node.Mass(term)).ToDense();
    const Eigen::MatrixXd b = (term < 0 ? by_field.Stiffness() : by_field.Mass(term)).ToDense();
    for (int i = 0; i < a.rows(); ++i) {
      for (int j = 0; j < a.cols(); ++j) {
        EXPECT_EQ(a(i, j), b(field_of_node[i], field_of_node[j])) << term << " " << i << " " << j;
      }
    }
  }
}

TEST(BeamModelTest, FieldNumberingPermutesTheNodeNumbering) {
  BeamDescription beam = UniformBeam(1e-4, test::Silicon(), test::ReferenceSection(), 6, 2);
  beam.supports.front() = Support::kClamped;
  beam.supports[3] = Support::kPinned;
  beam.supports.back() = Support::kGuided;
  ExpectSameMatricesPermuted<2>(beam, 5, 3);
  ExpectSameMatricesPermuted<3>(beam, 11, 3);
}

TEST(BeamModelTest, SupportsRemoveExactlyTheirDegreesOfFreedom) {
  BeamDescription beam = UniformBeam(1e-4, test::Silicon(), test::ReferenceSection(), 4, 0);
  beam.supports.front() = Support::kPinned;
  beam.supports.back() = Support::kGuided;
  const BeamModel<3> spatial(beam);
  EXPECT_EQ(spatial.FreeDofCount(), 5 * 6 - 4 - 4);
  const BeamModel<2> planar(beam);
  EXPECT_EQ(planar.FreeDofCount(), 5 * 3 - 2 - 2);
  EXPECT_EQ(planar.dofs().Reduced(0, NodalDof::kUy), -1);
  EXPECT_GE(planar.dofs().Reduced(0, NodalDof::kRz), 0);
  EXPECT_EQ(planar.dofs().Reduced(4, NodalDof::kRz), -1);
  EXPECT_GE(planar.dofs().Reduced(4, NodalDof::kUy), 0);
}

TEST(BeamModelTest, RejectsBadDescriptionsNamingTheField) {
  BeamDescription beam = UniformBeam(1e-4, test::Silicon(), test::ReferenceSection(), 2, 1);
  beam.elements[1].material.young_modulus = -1;
  try {
    BeamModel<2> model(beam);
    FAIL() << "accepted a negative modulus";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("elements[1].material.young_modulus = -1"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(UniformBeam(1e-4, test::Silicon(), test::ReferenceSection(), 0, 1),
               std::invalid_argument);
  EXPECT_THROW(UniformBeam(0.0, test::Silicon(), test::ReferenceSection(), 3, 1),
               std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
