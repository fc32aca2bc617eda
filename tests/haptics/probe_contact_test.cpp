// The probe against the beam's faces: the depth on every face against closed forms of smooth
// deflections, contact exactly when the sphere meets the box, the push out through the nearest
// face, a force continuous as the sphere rounds an edge, and the force and tangent against
// differences of an energy written here.
#include "cosmems/haptics/probe_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "force_differences.hpp"
#include "haptic_test_beam.hpp"

namespace cosmems {
namespace {

using test::kProbeCoupling;
using test::kProbeRadius;
using test::kReferenceLength;
using test::kReferenceThickness;
using test::kReferenceWidth;

BeamModel<3> SpatialCantilever(DofNumbering numbering = DofNumbering::kByField) {
  return BeamModel<3>(MakeStructure(StructureKind::kCantilever, kReferenceLength, test::Silicon(),
                                    test::ReferenceSection(), 20, 0),
                      numbering);
}

// u(x) = a x^2 + c x^3 [m], with a clamped root; Hermite cubics hold it exactly.
struct Cubic {
  double a = 0.0, c = 0.0;
  double operator()(double x) const { return a * x * x + c * x * x * x; }
  double Slope(double x) const { return 2 * a * x + 3 * c * x * x; }
};

// The state holding u_y = uy(x), u_z = uz(x) (slope -r_y in the x-z plane) and u_x = strain x.
template <int Dim>
Eigen::VectorXd SmoothState(const BeamModel<Dim>& model, Cubic uy, Cubic uz, double strain) {
  const double unit = model.units().length;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (std::size_t k = 0; k < model.NodeX().size(); ++k) {
    const int node = static_cast<int>(k);
    const double x = model.NodeX()[k] * unit;
    auto set = [&](NodalDof dof, double value) {
      if (FrameLayout<Dim>::kIndex[static_cast<int>(dof)] < 0) return;
      const int r = model.dofs().Reduced(node, dof);
      if (r >= 0) d[r] = value;
    };
    set(NodalDof::kUx, strain * x / unit);
    set(NodalDof::kUy, uy(x) / unit);
    set(NodalDof::kRz, uy.Slope(x));
    set(NodalDof::kUz, uz(x) / unit);
    set(NodalDof::kRy, -uz.Slope(x));
  }
  return d;
}

TEST(ProbeContactTest, EachFaceFollowsTheBeamUnderTheSphere) {
  const BeamModel<3> model = SpatialCantilever();
  ProbeContact<3> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Cubic uy{-20.0, 1e4}, uz{3.0, -2e3};
  const double strain = 1e-4;
  const Eigen::VectorXd d = SmoothState(model, uy, uz, strain);
  const double x = 123.4e-6, depth = 0.1e-6;  // inside element 12
  struct Case {
    Eigen::Vector3d centre;
    ProbeFace face;
  };
  const Case cases[] = {
      {{x, uy(x) + 0.5 * kReferenceThickness + kProbeRadius - depth, 3e-6}, ProbeFace::kUpper},
      {{x, uy(x) - 0.5 * kReferenceThickness - kProbeRadius + depth, -4e-6}, ProbeFace::kLower},
      {{x, uy(x), uz(x) + 0.5 * kReferenceWidth + kProbeRadius - depth}, ProbeFace::kPositiveZ},
      {{x, uy(x) + 0.2e-6, uz(x) - 0.5 * kReferenceWidth - kProbeRadius + depth},
       ProbeFace::kNegativeZ},
      {{kReferenceLength * (1 + strain) + kProbeRadius - depth, uy(kReferenceLength), 1e-6},
       ProbeFace::kLastEnd},
      {{-kProbeRadius + depth, 0.0, 0.0}, ProbeFace::kFirstEnd},
  };
  // Outward normals in ProbeFace order.
  const Eigen::Vector3d normals[] = {Eigen::Vector3d::UnitY(),  -Eigen::Vector3d::UnitY(),
                                     Eigen::Vector3d::UnitZ(),  -Eigen::Vector3d::UnitZ(),
                                     -Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX()};
  for (const Case& c : cases) {
    probe.MoveTo(c.centre);
    const ProbeTouch touch = probe.Touch(d);
    EXPECT_EQ(touch.face, c.face) << c.centre.transpose();
    // Within 1e-12 m: the cubics are exact, the rest is round-off of micrometre positions. The
    // -z case sits 0.2 um off the section's centre: the side is taken unbounded in y.
    EXPECT_NEAR(touch.depth_m, depth, 1e-12) << c.centre.transpose();
    EXPECT_EQ(touch.normal, normals[static_cast<int>(c.face)]);
    EXPECT_NEAR(touch.force_n, kProbeCoupling * depth, 1e-12 * kProbeCoupling);
  }
}

// The box at the section under the centre: 0 <= x <= L, |y - w(x_c)| <= t/2, |z| <= b/2.
double DistanceToBox(const Eigen::Vector3d& p, double w) {
  const Eigen::Vector3d low(0.0, w - 0.5 * kReferenceThickness, -0.5 * kReferenceWidth);
  const Eigen::Vector3d high(kReferenceLength, w + 0.5 * kReferenceThickness,
                             0.5 * kReferenceWidth);
  return (p - p.cwiseMax(low).cwiseMin(high)).norm();
}

TEST(ProbeContactTest, ItTouchesExactlyWhenTheSphereMeetsTheBox) {
  const BeamModel<2> model = test::HapticCantilever();
  ProbeContact<2> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Cubic uy{-30.0, 5e3};
  const Eigen::VectorXd d = SmoothState(model, uy, {}, 0.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> along(kReferenceLength - 40e-6, kReferenceLength + 3e-6),
      across(-13e-6, 13e-6), height(-5e-6, 5e-6);
  int touching = 0, apart = 0;
  for (int i = 0; i < 20000; ++i) {
    const double x = along(random);
    const Eigen::Vector3d p(x, uy(std::min(x, kReferenceLength)) + height(random), across(random));
    const double distance = DistanceToBox(p, uy(std::min(x, kReferenceLength)));
    if (std::abs(distance - kProbeRadius) < 1e-12) continue;  // on the boundary: either is right
    probe.MoveTo(p);
    const bool touches = probe.Touch(d).depth_m > 0.0;
    EXPECT_EQ(touches, distance < kProbeRadius) << p.transpose();
    (touches ? touching : apart) += 1;
  }
  EXPECT_GT(touching, 2000);  // both kinds well sampled
  EXPECT_GT(apart, 2000);
}

TEST(ProbeContactTest, FromInsideItPushesOutThroughTheNearestFace) {
  const BeamModel<3> model = SpatialCantilever();
  ProbeContact<3> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  probe.MoveTo(Eigen::Vector3d(100e-6, 0.2e-6, 9.5e-6));  // 0.5 um from the +z side, 0.8 the top
  ProbeTouch touch = probe.Touch(d);
  EXPECT_EQ(touch.face, ProbeFace::kPositiveZ);
  EXPECT_NEAR(touch.depth_m, kProbeRadius + 0.5e-6, 1e-15);
  probe.MoveTo(Eigen::Vector3d(100e-6, -0.7e-6, 2e-6));  // 0.3 um above the lower face
  touch = probe.Touch(d);
  EXPECT_EQ(touch.face, ProbeFace::kLower);
  EXPECT_NEAR(touch.depth_m, kProbeRadius + 0.3e-6, 1e-15);
}

// A hand pressing hard sinks the sphere past the beam's mid-plane, where the lower face overlaps
// it less than the upper one: the face it came in by keeps pushing until its overlap ends.
TEST(ProbeContactTest, PressedPastTheMidPlaneItPushesThroughTheFaceItCameIn) {
  const BeamModel<2> model = test::HapticCantilever();
  ProbeContact<2> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const Eigen::Vector3d below_mid(100e-6, -0.5e-6, 0.0);
  probe.MoveTo(below_mid);
  EXPECT_EQ(probe.Touch(d).face, ProbeFace::kLower);  // met there first: the least overlap
  probe.MoveTo(Eigen::Vector3d(100e-6, 0.5 * kReferenceThickness + kProbeRadius - 0.1e-6, 0.0));
  probe.Commit(d);
  probe.MoveTo(below_mid);
  ProbeTouch touch = probe.Touch(d);
  EXPECT_EQ(touch.face, ProbeFace::kUpper);
  EXPECT_NEAR(touch.depth_m, 0.5 * kReferenceThickness + 0.5e-6 + kProbeRadius, 1e-15);
  probe.Commit(d);
  // Through the beam and out below, the hand still feels the upper face: its overlap has not ended.
  probe.MoveTo(Eigen::Vector3d(100e-6, -0.5 * kReferenceThickness - kProbeRadius - 0.1e-6, 0.0));
  probe.Commit(d);
  EXPECT_EQ(probe.Touch(d).face, ProbeFace::kUpper);
  EXPECT_NEAR(probe.Touch(d).depth_m, kReferenceThickness + 2 * kProbeRadius + 0.1e-6, 1e-15);
  probe.MoveTo(Eigen::Vector3d(100e-6, 0.5 * kReferenceThickness + kProbeRadius + 0.1e-6,
                               0.0));  // lifted off
  probe.Commit(d);
  probe.MoveTo(Eigen::Vector3d(100e-6, -0.5 * kReferenceThickness - kProbeRadius + 0.1e-6,
                               0.0));  // in below
  probe.Commit(d);
  probe.MoveTo(Eigen::Vector3d(100e-6, 0.5e-6, 0.0));  // and up past the mid-plane
  touch = probe.Touch(d);
  EXPECT_EQ(touch.face, ProbeFace::kLower);
  EXPECT_NEAR(touch.depth_m, 0.5 * kReferenceThickness + 0.5e-6 + kProbeRadius, 1e-15);
}

// A prediction that carries the beam off the face the sphere held at the last accepted step
// lets go (NonlinearForce::LetsGo); one that keeps it pressed, or a sphere the hand moved off the
// face, or one that never touched, does not.
TEST(ProbeContactTest, APredictionLetsGoOnlyOfTheFaceItHeld) {
  const BeamModel<2> model = test::HapticCantilever();
  ProbeContact<2> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const double unit = model.units().length;
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(model.FreeDofCount());
  const auto lowered = [&](double drop_m) {  // the beam moved down by drop_m under the sphere
    Eigen::VectorXd d = rest;
    for (std::size_t k = 0; k < model.NodeX().size(); ++k) {
      const int r = model.dofs().Reduced(static_cast<int>(k), NodalDof::kUy);
      if (r >= 0) d[r] = -drop_m / unit;
    }
    return d;
  };
  const double top = 0.5 * kReferenceThickness + kProbeRadius;  // the centre touching the top
  const Eigen::Vector3d pressing(100e-6, top - 0.1e-6, 0.0);
  probe.MoveTo(pressing);
  EXPECT_FALSE(probe.LetsGo(rest, lowered(0.2e-6)));         // no face held yet
  probe.Commit(rest);                                        // the upper face held from here
  EXPECT_TRUE(probe.LetsGo(rest, lowered(0.2e-6)));          // predicted 0.1 um clear
  EXPECT_FALSE(probe.LetsGo(rest, lowered(0.05e-6)));        // still 0.05 um pressed
  probe.MoveTo(Eigen::Vector3d(100e-6, top + 0.1e-6, 0.0));  // the hand lifted off
  EXPECT_FALSE(probe.LetsGo(rest, lowered(0.2e-6)));
}

// The force's depth max(delta, 0) along a path in 1 nm steps: no step moves it by more than the
// largest slope of the overlaps where they are positive (sqrt(r^2 - h^2) at h <= sqrt(3) um,
// slope sqrt(3)) times the step.
double LargestJump(ProbeContact<3>& probe, const Eigen::VectorXd& d, const Eigen::Vector3d& from,
                   const Eigen::Vector3d& to) {
  const int steps = 8000;
  double previous = 0.0, largest = 0.0;
  for (int i = 0; i <= steps; ++i) {
    probe.MoveTo(from + (to - from) * i / steps);
    const double depth = std::max(0.0, probe.Touch(d).depth_m);
    if (i > 0) largest = std::max(largest, std::abs(depth - previous));
    previous = depth;
  }
  return largest;
}

TEST(ProbeContactTest, TheForceIsContinuousAroundTheEdges) {
  const BeamModel<3> model = SpatialCantilever();
  ProbeContact<3> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const double top = 0.5 * kReferenceThickness, side = 0.5 * kReferenceWidth, step = 1e-9;
  // Over the tip's upper edge, over the side's upper edge, down past the side.
  EXPECT_LT(LargestJump(probe, d, {kReferenceLength - 4e-6, top + 1e-6, 0.0},
                        {kReferenceLength + 4e-6, top + 1e-6, 0.0}),
            1.8 * step);
  EXPECT_LT(
      LargestJump(probe, d, {100e-6, top + 1e-6, side - 4e-6}, {100e-6, top + 1e-6, side + 4e-6}),
      1.8 * step);
  EXPECT_LT(
      LargestJump(probe, d, {100e-6, top + 4e-6, side + 1e-6}, {100e-6, -top - 4e-6, side + 1e-6}),
      1.8 * step);
}

// The coupling's energy with the face's field interpolated here, independently of the class: the
// Hermite cubics of element e on its nodal values (u1, slope1, u2, slope2), the slope being r_z
// for u_y and -r_y for u_z; linear u_x at the tip; with `twisting`, the upper and lower faces'
// point at z_c lowered by r_x z_c, r_x linear along the element.
struct FaceEnergy {
  const BeamModel<3>& model;
  Eigen::Vector3d centre;
  ProbeFace face;
  bool twisting = false;

  double Value(const Eigen::VectorXd& d, int node, NodalDof dof) const {
    const int r = model.dofs().Reduced(node, dof);
    return r >= 0 ? d[r] : 0.0;
  }
  double Field(const Eigen::VectorXd& d, NodalDof u, NodalDof rotation, double slope_sign) const {
    const UnitSystem& unit = model.units();
    const double x = centre.x() / unit.length;
    int e = 0;
    while (e + 1 < model.ElementCount() && model.NodeX()[e + 1] <= x) ++e;
    const double h = model.NodeX()[e + 1] - model.NodeX()[e];
    const double xi = (x - model.NodeX()[e]) / h;
    const double u1 = Value(d, e, u), u2 = Value(d, e + 1, u);
    const double s1 = slope_sign * Value(d, e, rotation);
    const double s2 = slope_sign * Value(d, e + 1, rotation);
    const double v = (2 * xi * xi * xi - 3 * xi * xi + 1) * u1 +
                     h * (xi * xi * xi - 2 * xi * xi + xi) * s1 +
                     (-2 * xi * xi * xi + 3 * xi * xi) * u2 + h * (xi * xi * xi - xi * xi) * s2;
    return v * unit.length;
  }
  // u_y at the face's point under the centre [m].
  double FaceY(const Eigen::VectorXd& d) const {
    const double w = Field(d, NodalDof::kUy, NodalDof::kRz, 1.0);
    if (!twisting) return w;
    const double x = centre.x() / model.units().length;
    int e = 0;
    while (e + 1 < model.ElementCount() && model.NodeX()[e + 1] <= x) ++e;
    const double xi = (x - model.NodeX()[e]) / (model.NodeX()[e + 1] - model.NodeX()[e]);
    const double twist =
        (1 - xi) * Value(d, e, NodalDof::kRx) + xi * Value(d, e + 1, NodalDof::kRx);
    return w - twist * std::clamp(centre.z(), -0.5 * kReferenceWidth, 0.5 * kReferenceWidth);
  }
  double operator()(const Eigen::VectorXd& d) const {
    const UnitSystem& unit = model.units();
    double delta = 0.0;  // m; the sphere is over the faces in these cases
    switch (face) {
      case ProbeFace::kUpper:
        delta = FaceY(d) + 0.5 * kReferenceThickness - (centre.y() - kProbeRadius);
        break;
      case ProbeFace::kLower:
        delta = centre.y() + kProbeRadius - (FaceY(d) - 0.5 * kReferenceThickness);
        break;
      case ProbeFace::kPositiveZ:
        delta = Field(d, NodalDof::kUz, NodalDof::kRy, -1.0) + 0.5 * kReferenceWidth -
                (centre.z() - kProbeRadius);
        break;
      default:  // the tip's end
        delta = kReferenceLength + Value(d, model.ElementCount(), NodalDof::kUx) * unit.length -
                (centre.x() - kProbeRadius);
    }
    const double k = kProbeCoupling / (unit.force / unit.length);
    const double depth = std::max(0.0, delta / unit.length);
    return 0.5 * k * depth * depth;
  }
};

TEST(ProbeContactTest, ForceAndTangentMatchDifferencesOfTheEnergyOnEveryFace) {
  const BeamModel<3> model = SpatialCantilever();
  ProbeContact<3> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (int i = 0; i < d.size(); ++i) d[i] = -1e-4 * std::sin(0.3 * i);  // a wavy state
  const double x = 133e-6, depth = 0.2e-6;
  const FaceEnergy cases[] = {
      {model, {x, 0.5 * kReferenceThickness + kProbeRadius - depth, 1e-6}, ProbeFace::kUpper},
      {model, {x, -0.5 * kReferenceThickness - kProbeRadius + depth, 1e-6}, ProbeFace::kLower},
      {model, {x, 0.0, 0.5 * kReferenceWidth + kProbeRadius - depth}, ProbeFace::kPositiveZ},
      {model, {kReferenceLength + kProbeRadius - depth, 0.0, 0.0}, ProbeFace::kLastEnd},
  };
  for (const FaceEnergy& energy : cases) {
    probe.MoveTo(energy.centre);
    ASSERT_EQ(probe.Touch(d).face, energy.face);
    ASSERT_GT(probe.Touch(d).depth_m, 0.0);
    // Central differences of a quadratic energy are exact up to round-off; h = 1e-6 of the
    // internal unit balances truncation (zero here) against cancellation (1e-16 / 1e-6).
    test::ExpectForceAndTangentMatchDifferences(probe, d, model.Stiffness().bandwidth(), energy,
                                                1e-6, 1e-7);
  }
  // Numbered node by node, a press off the axis twists the beam.
  const BeamModel<3> by_node = SpatialCantilever(DofNumbering::kByNode);
  ProbeContact<3> twisting(by_node, ProbeOptions{kProbeRadius, kProbeCoupling});
  d.setZero(by_node.FreeDofCount());
  for (int i = 0; i < d.size(); ++i) d[i] = -1e-4 * std::sin(0.3 * i);
  for (const FaceEnergy& energy :
       {FaceEnergy{by_node,
                   {x, 0.5 * kReferenceThickness + kProbeRadius - depth, 7e-6},
                   ProbeFace::kUpper,
                   true},
        FaceEnergy{by_node,
                   {x, -0.5 * kReferenceThickness - kProbeRadius + depth, -6e-6},
                   ProbeFace::kLower,
                   true}}) {
    twisting.MoveTo(energy.centre);
    ASSERT_EQ(twisting.Touch(d).face, energy.face);
    test::ExpectForceAndTangentMatchDifferences(twisting, d, by_node.Stiffness().bandwidth(),
                                                energy, 1e-6, 1e-7);
  }
}

TEST(ProbeContactTest, BesideTheBeamOrLostItTouchesNothing) {
  const BeamModel<2> model = test::HapticCantilever();
  ProbeContact<2> probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  Eigen::VectorXd r = Eigen::VectorXd::Zero(d.size());
  ForceTangent tangent(static_cast<int>(d.size()), model.Stiffness().bandwidth());
  tangent.Clear();
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(100e-6, 0.0, 15e-6),  // beside the 20 um wide strip, deep down
        Eigen::Vector3d(205e-6, 0.0, 0.0),    // beyond the tip by more than the radius
        Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0)}) {
    probe.MoveTo(p);
    ASSERT_TRUE(probe.Evaluate(d, r, tangent));
    EXPECT_EQ(r.norm(), 0.0);
    EXPECT_EQ(probe.Touch(d).force_n, 0.0);
  }
  // Just past the tip and above it, the sphere clears the tip's upper edge by sqrt(r^2 - h^2).
  probe.MoveTo(Eigen::Vector3d(201e-6, 1e-6 + 2e-6 - 0.1e-6, 0.0));
  const ProbeTouch touch = probe.Touch(d);
  EXPECT_EQ(touch.face, ProbeFace::kUpper);
  EXPECT_NEAR(touch.depth_m, 0.1e-6 + std::sqrt(4e-12 - 1e-12) - 2e-6, 1e-15);
}

}  // namespace
}  // namespace cosmems
