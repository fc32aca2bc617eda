#include "cosmems/rod/so3.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "test_beams.hpp"

namespace cosmems {
namespace {

// Round-off of a few quaternion products and trigonometric calls.
using test::kRoundOff;

Eigen::Vector3d RandomUnit(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

TEST(So3Test, ExponentialIsEigensAngleAxisAtAnyAngle) {
  std::mt19937 rng(7);
  for (double angle : {0.0, 1e-9, 1e-5, 0.3, 3.0, kPi, 4.0, 2.0 * kPi, 7.5, 20.0}) {
    const Eigen::Vector3d axis = RandomUnit(rng);
    const Eigen::Quaterniond q = QuaternionExp(angle * axis);
    const Eigen::Matrix3d expected = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    EXPECT_LT((q.toRotationMatrix() - expected).norm(), kRoundOff) << "angle " << angle;
    EXPECT_NEAR(q.norm(), 1.0, kRoundOff);
  }
}

TEST(So3Test, LogarithmInvertsExponentialUpToPiAndIgnoresTheSign) {
  std::mt19937 rng(11);
  for (double angle : {0.0, 1e-9, 1e-4, 0.2, 0.9, 2.0, 3.0, kPi - 1e-7}) {
    const Eigen::Vector3d theta = angle * RandomUnit(rng);
    const Eigen::Quaterniond q = QuaternionExp(theta);
    EXPECT_LT((QuaternionLog(q) - theta).norm(), kRoundOff * (1.0 + angle)) << angle;
    Eigen::Quaterniond minus = q;
    minus.coeffs() *= -1.0;  // the same rotation: the double cover
    EXPECT_LT((QuaternionLog(minus) - theta).norm(), kRoundOff * (1.0 + angle)) << angle;
  }
  // Beyond pi the principal vector is the complementary rotation about the opposite axis.
  const Eigen::Vector3d axis = RandomUnit(rng);
  EXPECT_LT((QuaternionLog(QuaternionExp(4.0 * axis)) + (2.0 * kPi - 4.0) * axis).norm(),
            kRoundOff);
}

TEST(So3Test, LiftNearAReferenceFollowsRotationsPastPi) {
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
  Eigen::Vector3d lifted = Eigen::Vector3d::Zero();
  // A rotation growing in small steps to 3.5 turns is tracked without wrapping.
  for (int k = 1; k <= 700; ++k) {
    const double angle = 7.0 * kPi * k / 700.0;
    lifted = RotationVectorNear(QuaternionExp(angle * axis), lifted);
    ASSERT_LT((lifted - angle * axis).norm(), 1e-11) << "angle " << angle;
  }
}

TEST(So3Test, LeftJacobianMapsRotationVectorChangesToSpatialSpin) {
  std::mt19937 rng(5);
  // Central differences: truncation ~eps^2 |theta|, round-off ~1e-16 / eps.
  constexpr double kStep = 1e-6;
  constexpr double kTolerance = 1e-8;
  for (double angle : {1e-5, 0.5, 2.0, 3.0, 5.0}) {
    const Eigen::Vector3d theta = angle * RandomUnit(rng);
    const Eigen::Matrix3d jl = LeftJacobian(theta);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d delta = kStep * Eigen::Vector3d::Unit(k);
      // exp((theta + d)^) exp(-(theta - d)^) = exp((2 J_l d)^) + O(d^3): its log / (2 eps).
      const Eigen::Quaterniond q =
          QuaternionExp(theta + delta) * QuaternionExp(theta - delta).conjugate();
      const Eigen::Vector3d spin = QuaternionLog(q) / (2.0 * kStep);
      EXPECT_LT((spin - jl.col(k)).norm(), kTolerance) << "angle " << angle;
    }
    if (angle < 2.0 * kPi) {
      EXPECT_LT((LeftJacobianInverse(theta) * jl - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    }
  }
}

TEST(So3Test, SkewIsTheCrossProduct) {
  const Eigen::Vector3d a(0.3, -1.2, 2.0);
  const Eigen::Vector3d b(-0.7, 0.4, 1.1);
  EXPECT_LT((Skew(a) * b - a.cross(b)).norm(), kRoundOff);
}

}  // namespace
}  // namespace cosmems
