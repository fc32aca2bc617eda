// The one stepping interface: each path's stepper marches exactly as the integrator it wraps, and
// a modal stepper's reads of single unknowns are the whole displacement's.
#include <gtest/gtest.h>

#include <cmath>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

constexpr int kSteps = 40;

// The microbridge (20 elements, planar) under a midspan load switched on at t = 0, at T1/20.
struct SteppedBridge {
  BeamModel<2> model{MakeStructure(StructureKind::kBridge, test::kReferenceLength, test::Silicon(),
                                   test::ReferenceSection(), 20, 0)};
  Eigen::MatrixXd pattern;
  double dt = 2.3e-6 / 20.0;  // s; f1 = 438 kHz
  SteppedBridge() {
    LoadCase loads;
    loads.points.push_back(
        {test::kReferenceLength / 2, Eigen::Vector3d(0, -1e-4, 0), Eigen::Vector3d::Zero()});
    pattern = AssembleLoads(model, loads);
  }
  Eigen::VectorXd Zero() const { return Eigen::VectorXd::Zero(model.FreeDofCount()); }
};

// kSteps steps of `stepper` and of `step(one)` on the integrator it wraps: the same states.
template <typename Direct>
void ExpectTheSameMarch(BeamStepper& stepper, Direct&& direct, const Eigen::VectorXd& d0) {
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(d0.size());
  const Eigen::VectorXd one = Eigen::VectorXd::Ones(1);
  ASSERT_EQ(stepper.Initialize(d0, zero, one), Status::kOk);
  for (int i = 0; i < kSteps; ++i) ASSERT_EQ(stepper.Step(one), Status::kOk) << i;
  const Eigen::VectorXd expected = direct();
  // Both run the same arithmetic in the same order: equal to the last bit.
  EXPECT_EQ((stepper.displacement() - expected).norm(), 0.0);
  EXPECT_GT(expected.norm(), 0.0);
}

TEST(BeamStepperTest, TheNewmarkPathsStepAsTheirIntegrators) {
  const SteppedBridge b;
  StepperOptions options;
  options.time_step = b.dt;
  options.parameters = GeneralizedAlphaParameters::FromSpectralRadius(0.8);
  const double dt = b.dt / b.model.units().time;
  const Eigen::VectorXd f = b.pattern.col(0), zero = b.Zero();
  {
    BeamStepperSetup linear = MakeBeamStepper(b.model, options, b.pattern, nullptr);
    ASSERT_EQ(linear.status, Status::kOk);
    ExpectTheSameMarch(
        *linear.stepper,
        [&] {
          LinearNewmarkIntegrator direct(b.model.Mass(0), b.model.Stiffness(), {},
                                         options.parameters, dt);
          EXPECT_EQ(direct.Initialize(zero, zero, f), Status::kOk);
          for (int i = 0; i < kSteps; ++i) EXPECT_EQ(direct.Step(f), Status::kOk);
          return direct.displacement();
        },
        zero);
    EXPECT_EQ(linear.stepper->last_stats().iterations, 0);  // the linear path has no Newton
  }
  StretchingForce<2> stepped(b.model), direct_force(b.model);
  BeamStepperSetup nonlinear = MakeBeamStepper(b.model, options, b.pattern, &stepped);
  ASSERT_EQ(nonlinear.status, Status::kOk);
  ExpectTheSameMarch(
      *nonlinear.stepper,
      [&] {
        NonlinearNewmarkIntegrator direct(b.model.Mass(0), b.model.Stiffness(), {}, direct_force,
                                          options.parameters, dt);
        EXPECT_EQ(direct.Initialize(zero, zero, f), Status::kOk);
        for (int i = 0; i < kSteps; ++i) EXPECT_EQ(direct.Step(f), Status::kOk);
        return direct.displacement();
      },
      zero);
  EXPECT_GT(nonlinear.stepper->last_stats().iterations, 0);
}

TEST(BeamStepperTest, TheModalPathsStepAsTheirIntegrators) {
  const SteppedBridge b;
  StepperOptions options;
  options.path = TimePath::kModal;
  options.time_step = b.dt;
  options.modes = 4;
  options.damping = DampingModel::QualityFactor(50);
  const double dt = b.dt / b.model.units().time;
  ModalOptions four;
  four.count = 4;
  const ModalModel modal =
      MakeModalModel(b.model, SolveModal(b.model, four), DampingModel::QualityFactor(50));
  const Eigen::VectorXd zero = b.Zero(), one = Eigen::VectorXd::Ones(1);
  // Started from a static deflection under half the load, so that the fit to the modes counts.
  const Eigen::VectorXd d0 = 0.5 * BandCholesky(b.model.Stiffness()).Solve(b.pattern.col(0));
  {
    BeamStepperSetup linear = MakeBeamStepper(b.model, options, b.pattern, nullptr);
    ASSERT_EQ(linear.status, Status::kOk);
    ExpectTheSameMarch(
        *linear.stepper,
        [&] {
          const Eigen::MatrixXd residual = modal.ResidualFlexibility(b.model, b.pattern);
          ModalPropagator direct(modal.coordinates, modal.shapes, b.pattern, residual, dt);
          direct.Initialize(modal.Project(b.model, (d0 - residual * one).eval()),
                            Eigen::VectorXd::Zero(4), one);
          for (int i = 0; i < kSteps; ++i) EXPECT_EQ(direct.Step(one), Status::kOk);
          Eigen::VectorXd d(d0.size());
          direct.Displacement(d);
          return d;
        },
        d0);
    // A watched point, read from the modal coordinates, is the whole displacement's: at the
    // midspan and at a quarter span (between nodes). 1e-12: the two sum in different orders.
    const Eigen::VectorXd& d = linear.stepper->displacement();
    for (double x : {0.5 * test::kReferenceLength, 0.27 * test::kReferenceLength}) {
      const OutputPoint point = OutputPoint::DeflectionAt(b.model, x);
      linear.stepper->Watch(point);
      const double expected = point.Evaluate(d);
      EXPECT_NEAR(linear.stepper->Watched(), expected, 1e-12 * std::abs(expected)) << x;
      EXPECT_NE(expected, 0.0);
    }
  }
  StretchingForce<2> stepped(b.model), direct_force(b.model);
  BeamStepperSetup nonlinear = MakeBeamStepper(b.model, options, b.pattern, &stepped);
  ASSERT_EQ(nonlinear.status, Status::kOk);
  ExpectTheSameMarch(
      *nonlinear.stepper,
      [&] {
        NonlinearModalIntegrator direct(b.model, modal, b.pattern, direct_force, dt);
        EXPECT_EQ(direct.Initialize(d0, zero, one), Status::kOk);
        for (int i = 0; i < kSteps; ++i) EXPECT_EQ(direct.Step(one), Status::kOk);
        return direct.displacement();
      },
      d0);
}

}  // namespace
}  // namespace cosmems
