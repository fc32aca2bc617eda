// The Cosserat element's gradient and tangent against finite differences of its energy, at
// random configurations with large rotations; the assembled rod's Newton matrix, with follower
// and moment load stiffness, against finite differences of its residual.
#include "cosmems/rod/cosserat_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "cosmems/rod/cosserat_rod.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using Vector12 = CosseratElement::Vector12;
using Matrix12 = CosseratElement::Matrix12;

// Central differences with step 1e-6: truncation ~1e-12 |W'''|, round-off ~1e-16 |W| / 1e-6,
// both about 1e-10 of the values compared here; 1e-7 leaves three decades of margin while any
// wrong term (of the size of the entries it belongs to) would show at 1e-1.
constexpr double kStep = 1e-6;
constexpr double kDifferenceTolerance = 1e-7;

// An element with the reference section's proportions in internal units (EA : kGA : EI_z =
// 1.2e5 : 4.1e4 : 1 per unit length), 50 to a rod, so the test sees the real stiffness ratios.
CosseratElement ReferenceElement() {
  const ElementSpec spec{test::kReferenceLength / 50, test::Silicon(), test::ReferenceSection()};
  const double ei = spec.material.young_modulus * spec.section.SecondMomentZ();
  const UnitSystem units =
      UnitSystem::ForBeam(test::kReferenceLength, ei, spec.material.density * spec.section.Area());
  // With a residual tension: the prestress must enter the gradient and tangent consistently.
  return CosseratElement::From(ElementProperties::From(spec, units), 5.0 / 6.0, 1.0, 3.0);
}

struct Configuration {
  Eigen::Vector3d du;  // u_b - u_a
  Eigen::Quaterniond qa, qb;
};

// Nodal rotations up to 2.5 pi (past pi, so the principal vectors wrap), relative rotations up
// to 2 rad, chords stretched and sheared by up to 5 % of h, and q_b's sign drawn at random.
Configuration RandomConfiguration(std::mt19937& rng, double h) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  auto vector = [&] { return Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)); };
  Configuration c;
  c.qa = QuaternionExp(2.5 * kPi * uniform(rng) * vector().normalized());
  c.qb = c.qa * QuaternionExp(2.0 * std::abs(uniform(rng)) * vector().normalized());
  if (uniform(rng) < 0.0) c.qb.coeffs() *= -1.0;
  // The chord follows the midpoint's axis, plus strain.
  const Eigen::Quaterniond mid = c.qa.slerp(0.5, c.qb);
  c.du = h * (mid * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX() + 0.05 * vector());
  return c;
}

// The configuration moved by x = (u_a, theta_a, u_b, theta_b) in the exponential chart.
Configuration Moved(const Configuration& c, const Vector12& x) {
  Configuration m;
  m.du = c.du + x.segment<3>(6) - x.segment<3>(0);
  m.qa = QuaternionExp(x.segment<3>(3)) * c.qa;
  m.qb = QuaternionExp(x.segment<3>(9)) * c.qb;
  return m;
}

// The gradient of the energy in the chart at x: J_l(theta)^T times the spatial gradient.
Vector12 ChartGradient(const CosseratElement& e, const Configuration& c, const Vector12& x) {
  const Configuration m = Moved(c, x);
  Vector12 g;
  CosseratElement::Kinematics k;
  e.Gradient(m.du, m.qa, m.qb, g, k);
  g.segment<3>(3) = LeftJacobian(x.segment<3>(3)).transpose() * g.segment<3>(3);
  g.segment<3>(9) = LeftJacobian(x.segment<3>(9)).transpose() * g.segment<3>(9);
  return g;
}

TEST(CosseratElementTest, GradientMatchesDifferencesOfTheEnergy) {
  const CosseratElement e = ReferenceElement();
  std::mt19937 rng(42);
  for (int trial = 0; trial < 40; ++trial) {
    const Configuration c = RandomConfiguration(rng, e.length);
    Vector12 g;
    CosseratElement::Kinematics kinematics;
    e.Gradient(c.du, c.qa, c.qb, g, kinematics);
    Vector12 difference;
    for (int k = 0; k < 12; ++k) {
      const Vector12 x = kStep * Vector12::Unit(k);
      const Configuration plus = Moved(c, x);
      const Configuration minus = Moved(c, -x);
      difference[k] =
          (e.Energy(plus.du, plus.qa, plus.qb) - e.Energy(minus.du, minus.qa, minus.qb)) /
          (2.0 * kStep);
    }
    EXPECT_LT((g - difference).norm(), kDifferenceTolerance * g.norm()) << "trial " << trial;
  }
}

TEST(CosseratElementTest, TangentMatchesDifferencesOfTheGradient) {
  const CosseratElement e = ReferenceElement();
  std::mt19937 rng(43);
  for (int trial = 0; trial < 40; ++trial) {
    const Configuration c = RandomConfiguration(rng, e.length);
    Vector12 g;
    CosseratElement::Kinematics kinematics;
    CosseratElement::Tangent tangent;
    e.Gradient(c.du, c.qa, c.qb, g, kinematics);
    e.Hessian(kinematics, tangent);
    const Matrix12 k = tangent.ToMatrix();
    Matrix12 difference;
    for (int j = 0; j < 12; ++j) {
      const Vector12 x = kStep * Vector12::Unit(j);
      difference.col(j) = (ChartGradient(e, c, x) - ChartGradient(e, c, -x)) / (2.0 * kStep);
    }
    EXPECT_LT((k - difference).norm(), kDifferenceTolerance * k.norm()) << "trial " << trial;
  }
}

TEST(CosseratElementTest, EnergyIsObjectiveAndBlindToTheQuaternionSign) {
  const CosseratElement e = ReferenceElement();
  std::mt19937 rng(44);
  const Eigen::Vector3d h = e.length * Eigen::Vector3d::UnitX();
  for (int trial = 0; trial < 10; ++trial) {
    const Configuration c = RandomConfiguration(rng, e.length);
    const double w = e.Energy(c.du, c.qa, c.qb);
    // A rigid rotation Q of the element: chord Q d, frames Q R.
    const Eigen::Quaterniond q = QuaternionExp(Eigen::Vector3d(2.0, -1.0, 3.0) * 0.7 * trial);
    const Eigen::Vector3d du = q * (h + c.du) - h;
    EXPECT_NEAR(e.Energy(du, q * c.qa, q * c.qb), w, 1e-12 * w);
    Eigen::Quaterniond minus = c.qa;
    minus.coeffs() *= -1.0;
    EXPECT_NEAR(e.Energy(c.du, minus, c.qb), w, 1e-12 * w);
  }
}

// At the undeformed state the tangent must be the linear one-point Timoshenko element: in the
// x-y plane with (v_a, rz_a, v_b, rz_b) and the midpoint shear strain
// gamma = (v_b - v_a)/h - (rz_a + rz_b)/2, K = EI_z/h [0 0 0 0; 0 1 0 -1; 0 0 0 0; 0 -1 0 1]
// + kGA h g g^T with g = (-1/h, -1/2, 1/h, -1/2).
TEST(CosseratElementTest, UndeformedTangentIsTheLinearTimoshenkoElement) {
  CosseratElement e = ReferenceElement();
  e.axial_prestress = 0.0;
  Vector12 g;
  CosseratElement::Kinematics kinematics;
  CosseratElement::Tangent tangent;
  e.Gradient(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity(),
             Eigen::Quaterniond::Identity(), g, kinematics);
  e.Hessian(kinematics, tangent);
  const Matrix12 k = tangent.ToMatrix();
  EXPECT_EQ(g.norm(), 0.0);
  const double h = e.length;
  const double ga = e.force_stiffness.y();
  const double ei = e.moment_stiffness.z();
  const std::vector<int> dofs = {1, 5, 7, 11};  // v_a, rz_a, v_b, rz_b
  Eigen::Matrix4d expected;
  expected << ga / h, ga / 2, -ga / h, ga / 2,                     //
      ga / 2, ei / h + ga * h / 4, -ga / 2, -ei / h + ga * h / 4,  //
      -ga / h, -ga / 2, ga / h, -ga / 2,                           //
      ga / 2, -ei / h + ga * h / 4, -ga / 2, ei / h + ga * h / 4;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      EXPECT_NEAR(k(dofs[i], dofs[j]), expected(i, j), 1e-12 * expected.norm()) << i << j;
    }
  }
  EXPECT_NEAR(k(0, 0), e.force_stiffness.x() / h, 1e-12 * k(0, 0));   // EA/h
  EXPECT_NEAR(k(3, 3), e.moment_stiffness.x() / h, 1e-12 * k(3, 3));  // GJ/h
}

// The residual of a whole rod in the chart: r_u and J_l(theta_i)^T r_theta at every node.
Eigen::VectorXd ChartResidual(const CosseratRod& rod, const RodState& state, const RodLoads& loads,
                              const Eigen::VectorXd& x) {
  RodState moved = state;
  moved.Update(x, 1.0);
  Eigen::VectorXd r(rod.DofCount());
  CosseratRod::ElementKinematics kinematics = rod.MakeKinematics();
  rod.InternalForces(moved, r, kinematics);
  rod.SubtractLoads(moved, loads, r, nullptr);
  for (int i = 0; i < rod.NodeCount(); ++i) {
    r.segment<3>(6 * i + 3) =
        LeftJacobian(x.segment<3>(6 * i + 3)).transpose() * r.segment<3>(6 * i + 3);
  }
  return r;
}

// The Newton matrix, with the non-symmetric stiffness of a follower force and of an end moment,
// is the derivative of the residual in the exponential chart.
TEST(CosseratRodTest, NewtonMatrixMatchesDifferencesOfTheResidualWithFollowerLoads) {
  const CosseratRod rod(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                      test::Silicon(), test::ReferenceSection(), 4, 0));
  std::mt19937 rng(45);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  RodState state = rod.UndeformedState();
  for (int i = 1; i < rod.NodeCount(); ++i) {  // a curled, twisted rod past pi at the tip
    state.displacement.col(i) = 0.3 * Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
    state.rotation.col(i) = QuaternionExp(1.1 * i * Eigen::Vector3d(0.4, -1.0, 0.8)).coeffs();
  }
  RodLoads loads = RodLoads::None(rod.NodeCount());  // internal units: O(1) here
  loads.dead_forces.col(2) = Eigen::Vector3d(0.5, -2.0, 1.0);
  loads.follower_force = Eigen::Vector3d(1.0, -3.0, 2.0);
  loads.end_moment = Eigen::Vector3d(2.0, 1.0, -1.5);
  BlockTridiagonalSystem system = rod.MakeSystem();
  CosseratRod::ElementKinematics kinematics = rod.MakeKinematics();
  Eigen::VectorXd r(rod.DofCount());
  rod.InternalForces(state, r, kinematics);
  rod.InternalTangent(kinematics, system);
  rod.SubtractLoads(state, loads, r, &system);
  const Eigen::MatrixXd k = system.ToDense();
  Eigen::MatrixXd difference(rod.DofCount(), rod.DofCount());
  for (int j = 0; j < rod.DofCount(); ++j) {
    const Eigen::VectorXd x = kStep * Eigen::VectorXd::Unit(rod.DofCount(), j);
    difference.col(j) =
        (ChartResidual(rod, state, loads, x) - ChartResidual(rod, state, loads, -x)) /
        (2.0 * kStep);
  }
  EXPECT_LT((k - difference).norm(), kDifferenceTolerance * k.norm());
  // The load stiffness alone is what makes it non-symmetric.
  const int tip = 6 * (rod.NodeCount() - 1);
  const Eigen::MatrixXd skew = 0.5 * (k - k.transpose());
  const Eigen::MatrixXd tip_block = skew.block(tip, tip, 6, 6);
  EXPECT_GT(tip_block.norm(), 1.0);
  EXPECT_LT(skew.topLeftCorner(tip, tip).norm(), 1e-12 * k.norm());
}

}  // namespace
}  // namespace cosmems
