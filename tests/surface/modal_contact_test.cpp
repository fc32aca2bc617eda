// Contact and stiction on the modal path (NonlinearModalIntegrator), against the propped
// cantilever's closed form, the energy of an impact, the S-shaped stuck cantilever's energy
// balance and the full model's Newmark path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cosmems/beam/load_vector.hpp"
#include "cosmems/surface/substrate_contact.hpp"
#include "cosmems/time/modal_propagator.hpp"
#include "cosmems/time/nonlinear_modal_integrator.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "modal_reduction.hpp"
#include "test_beams.hpp"
#include "thrown_cantilever.hpp"

namespace cosmems {
namespace {

using test::kReferenceGap;
using test::kReferenceLength;

Eigen::VectorXd TipPattern(const BeamModel<2>& model, double fy) {
  LoadCase loads;
  loads.points.push_back(
      {model.description().Length(), Eigen::Vector3d(0, fy, 0), Eigen::Vector3d::Zero()});
  return AssembleLoads(model, loads);
}

double Deflection(const BeamModel<2>& model, const Eigen::VectorXd& d, int node) {
  return d[model.dofs().Reduced(node, NodalDof::kUy)] * model.units().length;
}

// A cantilever pushed by three times the tip force that closes the gap, suddenly, comes to rest
// on its tip as the propped cantilever: tip on the substrate, w(L/2) = -5 g / 16. At rest the
// modal path's state is the full model's static one (the truncated modes answer statically), and
// the Hermite elements are exact for nodal loads, so the rest state differs from the closed form
// by the penetration the contact leaves (at most 1e-4 of the gap) and what the damping left of
// the motion: measured 3e-9 and 5e-9 of the gap at the tip and midspan, at orders 0 and 1 alike;
// the bound, 1e-6 of the gap, leaves room for rounding on other machines. 1 us steps, 1/14 of the
// first period, and 4 modes; the penetration stays within the tolerance at every step, the
// impact included.
TEST(ModalContactTest, SuddenlyPressedCantileverComesToRestPropped) {
  for (int order : {0, 1}) {
    const BeamModel<2> model = test::PlanarCantilever(kReferenceLength, 20, order);
    const double ei = test::Eiz();
    const double closing = 3.0 * ei * kReferenceGap / std::pow(kReferenceLength, 3);
    ContactOptions options;
    options.gap = kReferenceGap;
    SubstrateContact<2> contact(model, options);
    const ModalModel modal = test::ModalReduction(model, 4, DampingModel::QualityFactor(5.0));
    const double dt = 1e-6 / model.units().time;
    NonlinearModalIntegrator integrator(model, modal, TipPattern(model, -3.0 * closing), contact,
                                        dt);
    const int n = model.FreeDofCount();
    ASSERT_EQ(
        integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), test::Vec(1.0)),
        Status::kOk);
    double deepest = 0.0;
    for (int step = 0; step < 400; ++step) {
      ASSERT_EQ(integrator.Step(test::Vec(1.0)), Status::kOk)
          << "order " << order << ", step " << step;
      deepest = std::max(deepest, contact.Penetration(integrator.displacement()));
    }
    EXPECT_LE(deepest, contact.tolerance()) << "order " << order;
    EXPECT_EQ(contact.Summary().state, ContactState::kContact);
    const Eigen::VectorXd& d = integrator.displacement();
    const double tolerance = 1e-6 * kReferenceGap;
    EXPECT_NEAR(Deflection(model, d, 20), -kReferenceGap, tolerance) << "order " << order;
    EXPECT_NEAR(Deflection(model, d, 10), -5.0 / 16.0 * kReferenceGap, tolerance)
        << "order " << order;
  }
}

// The reference cantilever thrown at the substrate at 1 m/s (no adhesion), 8 modes and 10 ns
// steps: the penetration stays within the tolerance at every step and the energy
// (1/2 v^T M_0 v + 1/2 d^T K d, v the modes' velocity) never grows above its start, through
// several impacts (measured: 5 contacts, penetration 2e-13 m against the tolerance's 2e-10 m,
// largest energy the initial one). The velocity's projection at an impact and its fit back onto
// the modes are both orthogonal in the mass metric, so neither can add energy.
TEST(ModalContactTest, ImpactAtOneMeterPerSecondKeepsPenetrationAndGainsNoEnergy) {
  test::ExpectInelasticImpacts(test::ThrowAtTheSubstrate(
      3000,
      [](const BeamModel<2>& model, SubstrateContact<2>& contact, const Eigen::VectorXd& v0) {
        const int n = model.FreeDofCount();
        NonlinearModalIntegrator integrator(model, test::ModalReduction(model, 8, {}),
                                            Eigen::VectorXd::Zero(n), contact,
                                            10e-9 / model.units().time);
        EXPECT_EQ(integrator.Initialize(Eigen::VectorXd::Zero(n), v0, test::Vec(0.0)), Status::kOk);
        return integrator;
      },
      [](NonlinearModalIntegrator& integrator) { return integrator.Step(test::Vec(0.0)); }));
}

// A step of exactly the first period of an undamped modal model: a force held over it leaves
// the first mode where it would be without it, and G = R + Phi diag((b0 + b1)_q) Phi^T would be
// singular. The step runs (the mode takes 1e-6 of its static response instead, kHeldFloor): below
// the substrate's reach the state is the linear propagator's, which samples the first mode at its
// own period, to rounding; pressed by 3 times the closing force every step converges within the
// tolerance. (Sampled once a period, the first mode's swing onto the substrate falls between the
// steps: contact is held at the steps' ends, so a step must resolve the approach to see it.)
TEST(ModalContactTest, AStepOfExactlyTheFirstPeriodRuns) {
  const BeamModel<2> model = test::PlanarCantilever(kReferenceLength, 20, 0);
  const ModalModel modal = test::ModalReduction(model, 4, {});
  const double period = 2.0 * kPi / modal.coordinates[0].omega;
  const double closing = 3.0 * test::Eiz() * kReferenceGap / std::pow(kReferenceLength, 3);
  const int n = model.FreeDofCount();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (const double load : {0.2, 3.0}) {
    ContactOptions options;
    options.gap = kReferenceGap;
    SubstrateContact<2> contact(model, options);
    const Eigen::VectorXd pattern = TipPattern(model, -load * closing);
    NonlinearModalIntegrator integrator(model, modal, pattern, contact, period);
    ModalPropagator linear(modal.coordinates, modal.shapes, pattern,
                           modal.ResidualFlexibility(model, pattern), period);
    linear.Initialize(Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4), test::Vec(1.0));
    Eigen::VectorXd expected(n);
    linear.Displacement(expected);
    ASSERT_EQ(integrator.Initialize(expected, zero, test::Vec(1.0)), Status::kOk);
    for (int step = 1; step <= 20; ++step) {
      ASSERT_EQ(integrator.Step(test::Vec(1.0)), Status::kOk)
          << "load " << load << ", step " << step;
      ASSERT_TRUE(integrator.displacement().allFinite());
      EXPECT_LE(contact.Penetration(integrator.displacement()), contact.tolerance());
      ASSERT_EQ(linear.Step(test::Vec(1.0)), Status::kOk);
      if (load < 1.0) {
        linear.Displacement(expected);
        EXPECT_LE((integrator.displacement() - expected).norm(), 1e-12 * expected.norm())
            << "step " << step;
      }
    }
  }
}

// The same press on both paths, through the approach, the first impact, the rebound and the
// second contact (10 us): the full model by generalised-alpha (rho_inf = 0.6) at 4 ns steps, the
// modal path with 12 modes at 100 ns and at 20 ns. The modal path holds the reaction over each
// step, first order at an impact: the tip's largest difference measured 3.1e-7 m at 100 ns and
// 2.8e-8 m at 20 ns (16 % and 1.4 % of the gap; before the impact both are within 5e-10 m). The
// full model at 20 ns is itself 1e-7 m off its 4 ns run after the impact, hence the fine reference.
double LargestTipDifference(double modal_step) {
  const BeamModel<2> model = test::PlanarCantilever(kReferenceLength, 20, 0);
  const double closing = 3.0 * test::Eiz() * kReferenceGap / std::pow(kReferenceLength, 3);
  const Eigen::VectorXd pattern = TipPattern(model, -2.0 * closing);
  ContactOptions options;
  options.gap = kReferenceGap;
  SubstrateContact<2> full_contact(model, options), modal_contact(model, options);
  const UnitSystem& u = model.units();
  const int n = model.FreeDofCount();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  const double full_step = 4e-9;
  NonlinearNewmarkIntegrator full(model.Mass(0), model.Stiffness(), {}, full_contact,
                                  GeneralizedAlphaParameters::FromSpectralRadius(0.6),
                                  full_step / u.time);
  EXPECT_EQ(full.Initialize(zero, zero, pattern), Status::kOk);
  NonlinearModalIntegrator modal(model, test::ModalReduction(model, 12, {}), pattern, modal_contact,
                                 modal_step / u.time);
  EXPECT_EQ(modal.Initialize(zero, zero, test::Vec(1.0)), Status::kOk);
  const int per = static_cast<int>(std::lround(modal_step / full_step));
  double largest = 0.0;
  for (int step = 1; step * modal_step < 10e-6 * (1.0 + 1e-9); ++step) {
    if (modal.Step(test::Vec(1.0)) != Status::kOk) return std::numeric_limits<double>::infinity();
    for (int i = 0; i < per; ++i) {
      if (full.Step(pattern) != Status::kOk) return std::numeric_limits<double>::infinity();
    }
    const double difference =
        Deflection(model, modal.displacement(), 20) - Deflection(model, full.displacement(), 20);
    largest = std::max(largest, std::abs(difference));
  }
  EXPECT_GT(modal_contact.events().contacts, 0);
  return largest;
}

TEST(ModalContactTest, TipHistoryConvergesToTheFullModel) {
  const double coarse = LargestTipDifference(100e-9);
  const double fine = LargestTipDifference(20e-9);
  EXPECT_LT(coarse, 0.25 * kReferenceGap);
  EXPECT_LT(fine, 0.02 * kReferenceGap);
  EXPECT_LT(fine, 0.25 * coarse);
}

// Stiction on the modal path: a cantilever pressed flat by a distributed load that is then taken
// away peels back to the S shape of the energy-release-rate balance Gamma = 3 E t^3 g^2 / (2 s^4)
// when it is longer than that span, and springs free when it is shorter. Damped (Q = 2) so that it
// comes to rest within 200 us; the span is resolved to about an element, as in the static release
// (StictionTest). Let go at once, the peel runs dynamically to the tip, and the tip's reaction
// overshoots its static value as the beam swings up, so a beam in the arc range (0.71 to 1 of the
// span), which the quasi-static release leaves held by its tip, springs free here: measured at
// 0.75, 0.8, 0.9 and 0.95 of the span, with Q = 2 and 50, and on the full model (generalised-alpha,
// 50 ns steps) alike.
TEST(ModalContactTest, PressedAndReleasedCantileverSticksOrSpringsFree) {
  const double gamma = 0.02;
  const double e = test::Silicon().young_modulus, t = test::kReferenceThickness;
  const double span =
      std::pow(3.0 * e * t * t * t * kReferenceGap * kReferenceGap / (2.0 * gamma), 0.25);
  for (const double length : {0.8 * span, 1.5 * span}) {
    const int elements = 40;
    const BeamModel<2> model = test::PlanarCantilever(length, elements, 0);
    ContactOptions options;
    options.gap = kReferenceGap;
    options.stiction = true;
    options.adhesion_energy = gamma;
    SubstrateContact<2> contact(model, options);
    LoadCase press;
    press.distributed =
        Eigen::Vector3d(0, -8.0 * test::Eiz() * kReferenceGap / std::pow(length, 4) * 20.0, 0);
    const Eigen::VectorXd pattern = AssembleLoads(model, press);
    NonlinearModalIntegrator integrator(
        model, test::ModalReduction(model, 6, DampingModel::QualityFactor(2.0)), pattern, contact,
        0.5e-6 / model.units().time);
    const int n = model.FreeDofCount();
    ASSERT_EQ(
        integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), test::Vec(1.0)),
        Status::kOk);
    for (int step = 0; step < 1200; ++step) {  // 200 us pressed, 400 us let go
      const double s = step < 400 ? 1.0 : 0.0;
      ASSERT_EQ(integrator.Step(test::Vec(s)), Status::kOk)
          << "length " << length << ", step " << step;
      if (step == 399) {
        EXPECT_TRUE(contact.Summary().Stuck()) << "length " << length;
      }
    }
    const ContactSummary summary = contact.Summary();
    if (length < span) {
      EXPECT_EQ(summary.state, ContactState::kFree) << "length " << length;
    } else {
      ASSERT_TRUE(summary.Stuck());
      EXPECT_NEAR(summary.detached_length_m, span, 1.5 * length / elements);
    }
  }
}

}  // namespace
}  // namespace cosmems
