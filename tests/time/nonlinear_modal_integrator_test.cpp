// The modal path with a nonlinear force: without one it is the exact linear propagator, at rest
// it is the full model's nonlinear static equilibrium, and it refuses what it cannot carry.
#include "cosmems/time/nonlinear_modal_integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/time/modal_propagator.hpp"
#include "modal_reduction.hpp"
#include "no_force.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

using test::NoForce;

// A velocity-dependent force, which the modal path refuses.
class ViscousForce final : public NonlinearForce {
 public:
  bool Evaluate(const Eigen::VectorXd&, Eigen::VectorXd&, ForceTangent&) override { return true; }
  bool HasViscousPart() const override { return true; }
};

// A sudden tip load on the reference cantilever with 4 modes, a step of a quarter of the first
// period: with no force the state is ModalPropagator's (exact propagation, static correction) at
// every step, to rounding, at series orders 0 and 2.
TEST(NonlinearModalIntegratorTest, WithoutAForceItIsTheExactLinearPropagator) {
  for (int order : {0, 2}) {
    const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                           test::Silicon(), test::ReferenceSection(), 20, order));
    LoadCase loads;
    loads.points.push_back(
        {test::kReferenceLength, Eigen::Vector3d(0, -1e-6, 0), Eigen::Vector3d::Zero()});
    const Eigen::VectorXd pattern = AssembleLoads(model, loads);
    const ModalModel modal = test::ModalReduction(model, 4, DampingModel::QualityFactor(50.0));
    const double dt = 3.6e-6 / model.units().time;
    ModalPropagator linear(modal.coordinates, modal.shapes, pattern,
                           modal.ResidualFlexibility(model, pattern), dt);
    NoForce none;
    NonlinearModalIntegrator integrator(model, modal, pattern, none, dt);
    const int n = model.FreeDofCount();
    // The modes at rest under the load just applied: d = R P, the truncated modes' static part.
    linear.Initialize(Eigen::VectorXd::Zero(4), Eigen::VectorXd::Zero(4), test::Vec(1.0));
    Eigen::VectorXd expected(n);
    linear.Displacement(expected);
    ASSERT_EQ(integrator.Initialize(expected, Eigen::VectorXd::Zero(n), test::Vec(1.0)),
              Status::kOk);
    for (int step = 1; step <= 100; ++step) {
      ASSERT_EQ(linear.Step(test::Vec(1.0)), Status::kOk);
      ASSERT_EQ(integrator.Step(test::Vec(1.0)), Status::kOk);
      linear.Displacement(expected);
      ASSERT_LE((integrator.displacement() - expected).norm(), 1e-12 * expected.norm())
          << "order " << order << ", step " << step;
      ASSERT_LE((integrator.modal_velocity() - linear.modal_velocity()).norm(),
                1e-12 * linear.modal_velocity().norm() + 1e-300);
    }
  }
}

// A bridge loaded to a midspan deflection of about its thickness, where stretching doubles its
// stiffness: damped (Q = 2) modal dynamics with 4 modes and steps of a fifth of the first
// period come to rest at the full model's nonlinear static solution (SolveNonlinearStatic, a
// second method): the truncated modes answer statically through the force's own tangent. What
// the damping leaves after 200 periods is below 1e-9 of the deflection.
TEST(NonlinearModalIntegratorTest, StretchedBridgeComesToRestAtTheNonlinearStaticSolution) {
  const BeamModel<2> model(MakeStructure(StructureKind::kBridge, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 0));
  LoadCase loads;
  loads.distributed = Eigen::Vector3d(0, -2.0, 0);  // N/m
  StretchingForce<2> static_force(model), dynamic_force(model);
  const NonlinearStaticSolution solution = SolveNonlinearStatic(model, static_force, loads);
  ASSERT_EQ(solution.status, Status::kOk);
  const Eigen::VectorXd pattern = AssembleLoads(model, loads);
  const double linear_midspan =
      model.Stiffness().ToDense().llt().solve(pattern)[model.dofs().Reduced(10, NodalDof::kUy)];
  const double midspan = solution.displacement[model.dofs().Reduced(10, NodalDof::kUy)];
  ASSERT_LT(std::abs(midspan), 0.7 * std::abs(linear_midspan));  // stretching matters here
  const double period = 1.0 / 438e3 / model.units().time;
  NonlinearModalIntegrator integrator(
      model, test::ModalReduction(model, 4, DampingModel::QualityFactor(2.0)), pattern,
      dynamic_force, period / 5.0);
  const int n = model.FreeDofCount();
  ASSERT_EQ(
      integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), test::Vec(1.0)),
      Status::kOk);
  for (int step = 0; step < 1000; ++step) {
    ASSERT_EQ(integrator.Step(test::Vec(1.0)), Status::kOk) << "step " << step;
  }
  EXPECT_LE((integrator.displacement() - solution.displacement).norm(),
            1e-9 * solution.displacement.norm());
}

TEST(NonlinearModalIntegratorTest, RefusesAVelocityDependentForce) {
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 4, 0));
  ViscousForce viscous;
  const Eigen::VectorXd pattern = Eigen::VectorXd::Zero(model.FreeDofCount());
  EXPECT_THROW(
      NonlinearModalIntegrator(model, test::ModalReduction(model, 2, {}), pattern, viscous, 1.0),
      std::invalid_argument);
}

}  // namespace
}  // namespace cosmems
