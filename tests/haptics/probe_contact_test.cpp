// The probe against a structure's faces: on the reference cantilever's one-member netlist, the
// depth on every face against closed forms of smooth deflections, contact exactly when the sphere
// meets the box, the push out through the nearest face (never through the joint of two elements),
// a force continuous as the sphere rounds an edge, and the force and tangent against differences
// of an energy written here; on frames, the faces of members under loads and twists, and of a
// folded flexure's shuttle and beams.
#include "cosmems/haptics/probe_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "cosmems/analysis/frame_static_analysis.hpp"
#include "force_differences.hpp"
#include "haptics/haptic_test_beam.hpp"
#include "structure/test_frames.hpp"

namespace cosmems {
namespace {

using test::kProbeCoupling;
using test::kProbeRadius;
using test::kReferenceLength;
using test::kReferenceThickness;
using test::kReferenceWidth;

// The reference cantilever's netlist, spatial (with the twist coupled or not) or planar.
FrameModel SpatialChain(FrameCouplings couplings = FrameCouplings::kLinear) {
  return FrameModel(test::HapticCantileverNetlist(false), couplings);
}
FrameModel PlanarChain() { return FrameModel(test::HapticCantileverNetlist(true)); }

// u(x) = a x^2 + c x^3 [m], with a clamped root; Hermite cubics hold it exactly.
struct Cubic {
  double a = 0.0, c = 0.0;
  double operator()(double x) const { return a * x * x + c * x * x * x; }
  double Slope(double x) const { return 2 * a * x + 3 * c * x * x; }
};

// The value of a node's degree of freedom k (NodalDof order) in d; zero where anchored or absent.
double NodeValue(const FrameModel& model, const Eigen::VectorXd& d, int node, int k) {
  const int r = model.CarrierDof(model.mesh().nodes[node].carrier, k);
  return r >= 0 ? d[r] : 0.0;
}

// The state holding u_y = uy(x), u_z = uz(x) (slope -r_y in the x-z plane) and u_x = strain x.
Eigen::VectorXd SmoothState(const FrameModel& model, Cubic uy, Cubic uz, double strain) {
  const double unit = model.units().length;
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (const FrameMesh::Node& node : model.mesh().nodes) {
    const double x = node.position.x();
    const double values[6] = {strain * x / unit, uy(x) / unit, uz(x) / unit, 0.0,
                              -uz.Slope(x),      uy.Slope(x)};
    for (int k = 0; k < 6; ++k) {
      const int r = model.CarrierDof(node.carrier, k);
      if (r >= 0) d[r] = values[k];
    }
  }
  return d;
}

TEST(ProbeContactTest, EachFaceFollowsTheBeamUnderTheSphere) {
  const FrameModel model = SpatialChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
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
    EXPECT_TRUE(touch.normal.isApprox(normals[static_cast<int>(c.face)], 1e-15));
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
  const FrameModel model = PlanarChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
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

// From inside the member, at the joint of elements 10 and 11 and inside element 12, the sphere
// is pushed out through the nearest of the member's faces: no face stands between two elements.
TEST(ProbeContactTest, FromInsideItPushesOutThroughTheNearestFace) {
  const FrameModel model = SpatialChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (const double x : {100e-6, 123.4e-6}) {
    probe.MoveTo(Eigen::Vector3d(x, 0.2e-6, 9.5e-6));  // 0.5 um from the +z side, 0.8 the top
    ProbeTouch touch = probe.Touch(d);
    EXPECT_EQ(touch.face, ProbeFace::kPositiveZ) << x;
    EXPECT_NEAR(touch.depth_m, kProbeRadius + 0.5e-6, 1e-15);
    probe.MoveTo(Eigen::Vector3d(x, -0.7e-6, 2e-6));  // 0.3 um above the lower face
    touch = probe.Touch(d);
    EXPECT_EQ(touch.face, ProbeFace::kLower) << x;
    EXPECT_NEAR(touch.depth_m, kProbeRadius + 0.3e-6, 1e-15);
  }
  // 0.4 um from the tip's end, 0.9 from the top: out through the end.
  probe.MoveTo(Eigen::Vector3d(kReferenceLength - 0.4e-6, 0.1e-6, 0.0));
  EXPECT_EQ(probe.Touch(d).face, ProbeFace::kLastEnd);
  EXPECT_NEAR(probe.Touch(d).depth_m, kProbeRadius + 0.4e-6, 1e-15);
}

// A hand pressing hard sinks the sphere past the beam's mid-plane, where the lower face overlaps
// it less than the upper one: the face it came in by keeps pushing until its overlap ends.
TEST(ProbeContactTest, PressedPastTheMidPlaneItPushesThroughTheFaceItCameIn) {
  const FrameModel model = PlanarChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
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
  const FrameModel model = PlanarChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(model.FreeDofCount());
  const auto lowered = [&](double drop_m) {  // the beam moved down by drop_m under the sphere
    Eigen::VectorXd d = rest;
    for (const FrameMesh::Node& node : model.mesh().nodes) {
      const int r = model.CarrierDof(node.carrier, 1);
      if (r >= 0) d[r] = -drop_m / model.units().length;
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

// Touches(): the sphere pushes where it pushed nowhere at the last accepted step. Clear of the
// shuttle it does not; moved 0.3 um into its upper face it does, until a step pushing there is
// accepted (the face then held); let go and accepted clear, it touches again when it comes back.
TEST(ProbeContactTest, TouchesOnlyWhereItBeginsToPush) {
  const FrameModel model(test::FoldedFlexure(100e-6, 4));
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  ProbeContact probe(model, ProbeOptions{kProbeRadius, 5.0});
  const Eigen::Vector3d clear(5e-6, 1e-6 + kProbeRadius + 0.3e-6, 3e-6);
  const Eigen::Vector3d into(5e-6, 1e-6 + kProbeRadius - 0.3e-6, 3e-6);
  probe.MoveTo(clear);
  EXPECT_FALSE(probe.Touches(d));
  probe.MoveTo(into);
  EXPECT_TRUE(probe.Touches(d));
  probe.Commit(d);
  EXPECT_FALSE(probe.Touches(d));  // pushing, and pushed at the step accepted
  probe.MoveTo(clear);
  EXPECT_FALSE(probe.Touches(d));  // letting go is no touch
  probe.Commit(d);
  probe.MoveTo(into);
  EXPECT_TRUE(probe.Touches(d));
  probe.MoveTo(Eigen::Vector3d(0.0, 1.0, 0.0));  // out of reach
  EXPECT_FALSE(probe.Touches(d));
}

// The force's depth max(delta, 0) along a path in 1 nm steps: no step moves it by more than the
// largest slope of the overlaps where they are positive (sqrt(r^2 - h^2) at h <= sqrt(3) um,
// slope sqrt(3)) times the step.
double LargestJump(ProbeContact& probe, const Eigen::VectorXd& d, const Eigen::Vector3d& from,
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
  const FrameModel model = SpatialChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
  const Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  const double top = 0.5 * kReferenceThickness, side = 0.5 * kReferenceWidth, step = 1e-9;
  // Over the tip's upper edge, over the side's upper edge, down past the side, and along the
  // upper face across the joint of two elements.
  EXPECT_LT(LargestJump(probe, d, {kReferenceLength - 4e-6, top + 1e-6, 0.0},
                        {kReferenceLength + 4e-6, top + 1e-6, 0.0}),
            1.8 * step);
  EXPECT_LT(
      LargestJump(probe, d, {100e-6, top + 1e-6, side - 4e-6}, {100e-6, top + 1e-6, side + 4e-6}),
      1.8 * step);
  EXPECT_LT(
      LargestJump(probe, d, {100e-6, top + 4e-6, side + 1e-6}, {100e-6, -top - 4e-6, side + 1e-6}),
      1.8 * step);
  EXPECT_LT(LargestJump(probe, d, {96e-6, top + 1e-6, 0.0}, {104e-6, top + 1e-6, 0.0}), 1.8 * step);
}

// The element of the chain holding x and its xi there.
std::pair<int, double> ChainElement(const FrameModel& model, double x) {
  for (int e = 0; e < model.ElementCount(); ++e) {
    const FrameMesh::Element& element = model.mesh().elements[e];
    const double a = model.mesh().nodes[element.from].position.x();
    const double b = model.mesh().nodes[element.to].position.x();
    if (a <= x && x <= b) return {e, (x - a) / (b - a)};
  }
  return {-1, 0.0};
}

// The coupling's energy with the face's field interpolated here, independently of the class: the
// Hermite cubics of the element under the centre on its nodal values (u1, slope1, u2, slope2),
// the slope being r_z for u_y and -r_y for u_z; u_x of the tip; with `twisting`, the upper and
// lower faces' point at z_c lowered by r_x z_c, r_x linear along the element.
struct FaceEnergy {
  const FrameModel& model;
  Eigen::Vector3d centre;
  ProbeFace face;
  bool twisting = false;

  // The field u (NodalDof index) with its slope (rotation index, sign) under the centre [m].
  double Field(const Eigen::VectorXd& d, int u, int rotation, double slope_sign) const {
    const auto [e, xi] = ChainElement(model, centre.x());
    const FrameMesh::Element& element = model.mesh().elements[e];
    const double h = element.length / model.units().length;
    const double u1 = NodeValue(model, d, element.from, u);
    const double u2 = NodeValue(model, d, element.to, u);
    const double s1 = slope_sign * NodeValue(model, d, element.from, rotation);
    const double s2 = slope_sign * NodeValue(model, d, element.to, rotation);
    const double v = (2 * xi * xi * xi - 3 * xi * xi + 1) * u1 +
                     h * (xi * xi * xi - 2 * xi * xi + xi) * s1 +
                     (-2 * xi * xi * xi + 3 * xi * xi) * u2 + h * (xi * xi * xi - xi * xi) * s2;
    return v * model.units().length;
  }
  // u_y at the face's point under the centre [m].
  double FaceY(const Eigen::VectorXd& d) const {
    const double w = Field(d, 1, 5, 1.0);
    if (!twisting) return w;
    const auto [e, xi] = ChainElement(model, centre.x());
    const FrameMesh::Element& element = model.mesh().elements[e];
    const double twist =
        (1 - xi) * NodeValue(model, d, element.from, 3) + xi * NodeValue(model, d, element.to, 3);
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
        delta = Field(d, 2, 4, -1.0) + 0.5 * kReferenceWidth - (centre.z() - kProbeRadius);
        break;
      default:  // the tip's end; the tip is the netlist's node 1
        delta = kReferenceLength + NodeValue(model, d, 1, 0) * unit.length -
                (centre.x() - kProbeRadius);
    }
    const double k = kProbeCoupling / (unit.force / unit.length);
    const double depth = std::max(0.0, delta / unit.length);
    return 0.5 * k * depth * depth;
  }
};

TEST(ProbeContactTest, ForceAndTangentMatchDifferencesOfTheEnergyOnEveryFace) {
  const FrameModel model = SpatialChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
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
  // With the twist coupled, a press off the axis twists the member.
  const FrameModel twisting_model = SpatialChain(FrameCouplings::kTwist);
  ProbeContact twisting(twisting_model, ProbeOptions{kProbeRadius, kProbeCoupling});
  d.setZero(twisting_model.FreeDofCount());
  for (int i = 0; i < d.size(); ++i) d[i] = -1e-4 * std::sin(0.3 * i);
  for (const FaceEnergy& energy :
       {FaceEnergy{twisting_model,
                   {x, 0.5 * kReferenceThickness + kProbeRadius - depth, 7e-6},
                   ProbeFace::kUpper,
                   true},
        FaceEnergy{twisting_model,
                   {x, -0.5 * kReferenceThickness - kProbeRadius + depth, -6e-6},
                   ProbeFace::kLower,
                   true}}) {
    twisting.MoveTo(energy.centre);
    ASSERT_EQ(twisting.Touch(d).face, energy.face);
    test::ExpectForceAndTangentMatchDifferences(twisting, d, twisting_model.Stiffness().bandwidth(),
                                                energy, 1e-6, 1e-7);
  }
}

TEST(ProbeContactTest, BesideTheBeamOrLostItTouchesNothing) {
  const FrameModel model = PlanarChain();
  ProbeContact probe(model, ProbeOptions{kProbeRadius, kProbeCoupling});
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

// The clamped cantilever's deflection under a tip force P: P x^2 (3L - x) / (6 E I).
double TipLoadDeflection(double force, double ei, double x) {
  const double l = test::kReferenceLength;
  return force * x * x * (3.0 * l - x) / (6.0 * ei);
}

TEST(ProbeContactTest, FacesFollowTheMembersStaticShape) {
  const FrameModel model(test::HapticCantileverNetlist(false));
  const double py = -2e-7, pz = 1e-6;  // N: down 0.24 um, aside 12 nm at the tip
  FrameLoadCase tip;
  tip.points.push_back({1, -1, {0.0, py, pz}, {0.0, 0.0, 0.0}});
  const FrameStaticSolution solution = SolveFrameStatic(model, tip);
  ASSERT_EQ(solution.status, Status::kOk);
  const Eigen::VectorXd& d = solution.displacement;
  const RectangularSection s = test::ReferenceSection();
  const double eiz = test::Silicon().young_modulus * s.width * std::pow(s.thickness, 3) / 12.0;
  const double eiy = test::Silicon().young_modulus * s.thickness * std::pow(s.width, 3) / 12.0;
  ProbeContact probe(model, ProbeOptions{kProbeRadius, 5.0});
  const double x = 123.4e-6, depth = 0.1e-6;  // inside element 12, off its nodes
  const double w = TipLoadDeflection(py, eiz, x), v = TipLoadDeflection(pz, eiy, x);
  struct Case {
    Eigen::Vector3d centre;
    ProbeFace face;
    Eigen::Vector3d normal;
  };
  // Off the axis across the width: the faces' points turn with the twist, which a force through
  // the axis leaves at zero.
  const Case cases[] = {
      {{x, w + 0.5 * s.thickness + kProbeRadius - depth, 3e-6}, ProbeFace::kUpper, {0, 1, 0}},
      {{x, w - 0.5 * s.thickness - kProbeRadius + depth, -4e-6}, ProbeFace::kLower, {0, -1, 0}},
      {{x, 0.2e-6, v + 0.5 * s.width + kProbeRadius - depth}, ProbeFace::kPositiveZ, {0, 0, 1}},
      {{x, 0.0, v - 0.5 * s.width - kProbeRadius + depth}, ProbeFace::kNegativeZ, {0, 0, -1}},
      {{test::kReferenceLength + kProbeRadius - depth, 0.0, 2e-6}, ProbeFace::kLastEnd, {1, 0, 0}},
  };
  for (const Case& c : cases) {
    probe.MoveTo(c.centre);
    const ProbeTouch touch = probe.Touch(d);
    EXPECT_EQ(touch.face, c.face) << c.centre.transpose();
    // 1e-12 m: the Hermite cubics are exact for a tip load; the rest is round-off of micrometre
    // positions.
    EXPECT_NEAR(touch.depth_m, depth, 1e-12) << c.centre.transpose();
    EXPECT_TRUE(touch.normal.isApprox(c.normal, 1e-12)) << touch.normal.transpose();
  }
  // Out of reach beside the member; above it, the clearance is known at any height.
  probe.MoveTo(Eigen::Vector3d(x, 10e-6, 0.0));
  EXPECT_NEAR(probe.Touch(d).depth_m, w + 0.5 * s.thickness + kProbeRadius - 10e-6, 1e-12);
  probe.MoveTo(Eigen::Vector3d(x, 0.0, 0.5 * s.width + 1.5 * kProbeRadius));
  EXPECT_EQ(probe.Touch(d).depth_m, -std::numeric_limits<double>::infinity());
}

// In a planar frame that is no straight chain the twist shares the band with the out-of-plane
// bending (a straight chain numbers them apart and leaves the twist out, as the beam does): an L
// of the cantilever and a 50 um arm along z, twisted by a torque about x at the arm's end, which
// reaches the cantilever as a pure torque, theta_x linear along it (exact in the elements). The
// upper face's point at z_c across the width moves by (theta x arm)_y = -theta_x(x) z_c.
TEST(ProbeContactTest, AnUpperFaceOffTheAxisTurnsWithTheTwist) {
  StructureDescription l_frame = test::HapticCantileverNetlist(false);
  const int end = test::AddNode(l_frame, "end", {test::kReferenceLength, 0.0, 50e-6});
  l_frame.members.push_back(
      {1, end, test::Silicon(), test::ReferenceSection(), 5, Eigen::Vector3d::UnitY()});
  const FrameModel model(l_frame);
  FrameLoadCase torque;
  torque.points.push_back({end, -1, {0.0, 0.0, 0.0}, {1e-9, 0.0, 0.0}});
  const FrameStaticSolution twisted = SolveFrameStatic(model, torque);
  ASSERT_EQ(twisted.status, Status::kOk);
  const double x = 123.4e-6, z_c = 8e-6, depth = 0.1e-6;
  const double twist = twisted.nodes[1][3] * x / test::kReferenceLength;
  ASSERT_GT(std::abs(twist * z_c), 1e-8);  // a motion the check resolves
  ProbeContact probe(model, ProbeOptions{kProbeRadius, 5.0});
  const double top = 0.5 * test::kReferenceThickness + kProbeRadius - depth;
  probe.MoveTo(Eigen::Vector3d(x, top - twist * z_c, z_c));
  const ProbeTouch touch = probe.Touch(twisted.displacement);
  EXPECT_EQ(touch.face, ProbeFace::kUpper);
  // 1e-12 m as above.
  EXPECT_NEAR(touch.depth_m, depth, 1e-12);
}

// A random small state of `model`, in its internal units.
Eigen::VectorXd RandomState(const FrameModel& model, double scale_m) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd d(model.FreeDofCount());
  for (int i = 0; i < d.size(); ++i) d[i] = uniform(random) * scale_m / model.units().length;
  return d;
}

TEST(ProbeContactTest, ForceAndTangentAreTheCouplingEnergysDifferences) {
  const StructureDescription flexure = test::FoldedFlexure(100e-6, 4);
  const FrameModel model(flexure);
  const Eigen::VectorXd d = RandomState(model, 2e-9);
  // The shuttle is 40 x 2 x 40 um at the origin; its beams leave along z from its edges at
  // z = +-20 um. Element 0 is the first quarter of an inner beam, 2 x 2 um.
  const FrameMesh::Element& element = model.mesh().elements[0];
  const Eigen::Vector3d middle =
      0.5 * (model.mesh().nodes[element.from].position + model.mesh().nodes[element.to].position);
  const Eigen::Vector3d across = element.axes.row(2).transpose(), up = Eigen::Vector3d::UnitY();
  struct Case {
    Eigen::Vector3d centre;
    ProbeFace face;
  };
  const double in = kProbeRadius - 0.3e-6;  // the sphere 0.3 um into a face at rest
  const Case cases[] = {
      {{5e-6, 1e-6 + in, 3e-6}, ProbeFace::kUpper},        // the shuttle from above, off centre
      {{20e-6 + in, 0.2e-6, -4e-6}, ProbeFace::kLastEnd},  // its +x side
      {{-20e-6 - in, 0.0, 6e-6}, ProbeFace::kFirstEnd},    // its -x side
      {{5e-6, -1e-6 - in, -12e-6}, ProbeFace::kLower},     // from below
      // A member's faces off its axis move with its bendings and its twist.
      {middle + 0.5e-6 * across + (1e-6 + in) * up, ProbeFace::kUpper},
      {middle + (1e-6 + in) * across + 0.3e-6 * up, ProbeFace::kPositiveZ},
  };
  const double length = model.units().length, force = model.units().force;
  for (const Case& c : cases) {
    ProbeContact probe(model, ProbeOptions{kProbeRadius, 5.0});  // holding no face
    probe.MoveTo(c.centre);
    probe.Commit(d);  // holds the face it presses
    const ProbeTouch touch = probe.Touch(d);
    ASSERT_EQ(touch.face, c.face) << c.centre.transpose();
    ASSERT_GT(touch.depth_m, 0.0);
    // The coupling's energy (k/2) delta^2 = F delta / 2, internal units.
    auto energy = [&](const Eigen::VectorXd& x) {
      const ProbeTouch t = probe.Touch(x);
      return 0.5 * (t.force_n / force) * std::max(0.0, t.depth_m / length);
    };
    // The force is linear in the overlap and the overlap affine in d: the differences are exact
    // up to round-off, 1e-7 of a step 1e-4 of the state.
    test::ExpectForceAndTangentMatchDifferences(probe, d, model.Stiffness().bandwidth(), energy,
                                                1e-4 * d.cwiseAbs().maxCoeff(), 1e-7);
  }
}

}  // namespace
}  // namespace cosmems
