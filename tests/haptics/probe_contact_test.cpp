// The probe's force and tangent against differences of its energy, and the press of a cantilever
// tip against the two springs in series it is.
#include "cosmems/haptics/probe_contact.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "force_differences.hpp"
#include "haptic_test_beam.hpp"

namespace cosmems {
namespace {

constexpr double kThickness = 2e-6;

// The coupling's energy with w(x) interpolated here, independently of the class: the Hermite
// cubics of element e on its nodal values (w1, theta1, w2, theta2), theta = dw/dx.
double Energy(const BeamModel<2>& model, const Eigen::VectorXd& d, int e, double xi, double k,
              double lowest) {
  const UnitSystem& u = model.units();
  auto value = [&](int node, NodalDof dof) {
    const int r = model.dofs().Reduced(node, dof);
    return r >= 0 ? d[r] : 0.0;
  };
  const double h = model.NodeX()[e + 1] - model.NodeX()[e];
  const double w1 = value(e, NodalDof::kUy), t1 = value(e, NodalDof::kRz);
  const double w2 = value(e + 1, NodalDof::kUy), t2 = value(e + 1, NodalDof::kRz);
  const double w = (2 * xi * xi * xi - 3 * xi * xi + 1) * w1 +
                   h * (xi * xi * xi - 2 * xi * xi + xi) * t1 +
                   (-2 * xi * xi * xi + 3 * xi * xi) * w2 + h * (xi * xi * xi - xi * xi) * t2;
  const double delta = w * u.length + 0.5 * kThickness - lowest;  // m
  const double k_internal = k / (u.force / u.length);
  const double delta_internal = std::max(0.0, delta / u.length);
  return 0.5 * k_internal * delta_internal * delta_internal;
}

TEST(ProbeContactTest, ForceAndTangentMatchDifferencesOfTheEnergy) {
  const BeamModel<2> model = test::HapticCantilever();
  const double k = 5.0, radius = 2e-6;
  ProbeContact<2> probe(model, ProbeOptions{radius, k});
  // Over element 13 at xi = 0.3; the sphere's lowest point 0.2 um below the undeformed face.
  const double x = model.NodeX()[13] * model.units().length + 0.3 * 10e-6;
  const double lowest = 0.5 * kThickness - 0.2e-6;
  probe.MoveTo(Eigen::Vector3d(x, lowest + radius, 0.0));
  Eigen::VectorXd d = Eigen::VectorXd::Zero(model.FreeDofCount());
  for (int i = 0; i < d.size(); ++i) d[i] = -1e-3 * std::sin(0.3 * i);  // a wavy state
  ASSERT_GT(probe.Penetration(d), 0.0);
  // Central differences of a quadratic energy are exact up to round-off; h = 1e-6 of the
  // internal unit balances truncation (zero here) against cancellation (1e-16 / 1e-6).
  test::ExpectForceAndTangentMatchDifferences(
      probe, d, model.Stiffness().bandwidth(),
      [&](const Eigen::VectorXd& s) { return Energy(model, s, 13, 0.3, k, lowest); }, 1e-6, 1e-7);
}

TEST(ProbeContactTest, BesideTheBeamOrLostItTouchesNothing) {
  const BeamModel<2> model = test::HapticCantilever();
  ProbeContact<2> probe(model, ProbeOptions{2e-6, 5.0});
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
    EXPECT_EQ(probe.Reaction(d), 0.0);
  }
  // Just past the tip the sphere's side still touches the tip's edge: sqrt(r^2 - h^2) lower.
  probe.MoveTo(Eigen::Vector3d(201e-6, 1e-6 + 2e-6 - 0.1e-6, 0.0));
  EXPECT_NEAR(probe.Penetration(d), 0.1e-6 + std::sqrt(4e-12 - 1e-12) - 2e-6, 1e-15);
}

}  // namespace
}  // namespace cosmems
