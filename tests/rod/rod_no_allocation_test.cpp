// The Cosserat rod's hot paths allocate nothing: a Newton iteration, a warm-started static
// re-solve (with follower and moment loads, which take the unsymmetric end block) and a dynamic
// step, counted by allocation_counter.cpp (see tests/time/no_allocation_test.cpp).
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "cosmems/analysis/cosserat_static_solver.hpp"
#include "cosmems/time/cosserat_newmark_integrator.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

CosseratRod ReferenceCantilever() {
  return CosseratRod(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                   test::Silicon(), test::ReferenceSection(), 50, 0));
}

// A tip force of alpha EI/L^2 down, dead and follower, and a moment about z.
RodLoads TipLoads(const CosseratRod& rod, double alpha) {
  const double ei = test::Silicon().young_modulus * test::ReferenceSection().SecondMomentZ();
  const double force = alpha * ei / (test::kReferenceLength * test::kReferenceLength);
  return RodLoads::AtEnd(rod.NodeCount(), Eigen::Vector3d(0.0, -force, 0.0),
                         Eigen::Vector3d(0.0, 0.0, 0.3 * force),
                         Eigen::Vector3d(0.0, 0.0, 0.2 * force * test::kReferenceLength));
}

TEST(RodNoAllocationTest, NewtonIterationAllocatesNothing) {
  const CosseratRod rod = ReferenceCantilever();
  CosseratStaticSolver solver(rod);
  ASSERT_EQ(solver.Solve(TipLoads(rod, 2.0)), Status::kOk);
  RodLoads loads = RodLoads::None(rod.NodeCount());
  rod.ToInternal(TipLoads(rod, 2.5), loads);
  BlockTridiagonalSystem system = rod.MakeSystem();
  CosseratRod::ElementKinematics kinematics = rod.MakeKinematics();
  Eigen::VectorXd residual(rod.DofCount());
  Eigen::Matrix3Xd correction(3, rod.NodeCount());
  RodState state = solver.state();
  RodState next = state;
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(20,
                                    [&] {
                                      rod.InternalForces(state, residual, kinematics);
                                      rod.InternalTangent(kinematics, system);
                                      rod.SubtractLoads(state, loads, residual, &system);
                                      rod.ClearSupported(residual);
                                      status = system.Factorize();
                                      residual = -residual;
                                      system.SolveInPlace(residual);
                                      rod.Retract(state, residual, 1.0, next, correction);
                                      std::swap(state, next);
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
}

TEST(RodNoAllocationTest, WarmStaticResolveAllocatesNothing) {
  const CosseratRod rod = ReferenceCantilever();
  CosseratStaticSolver solver(rod);
  const RodLoads a = TipLoads(rod, 2.0);
  const RodLoads b = TipLoads(rod, 2.05);
  ASSERT_EQ(solver.Solve(a), Status::kOk);
  Status status = Status::kOk;
  int iterations = 0;
  EXPECT_EQ(test::AllocationsDuring(10,
                                    [&] {
                                      status = solver.Solve(b);
                                      iterations += solver.last_stats().iterations;
                                      if (status == Status::kOk) status = solver.Solve(a);
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(iterations, 0);  // Newton really iterated
}

TEST(RodNoAllocationTest, DynamicStepAllocatesNothing) {
  const CosseratRod rod = ReferenceCantilever();
  CosseratNewmarkIntegrator integrator(rod, GeneralizedAlphaParameters::Newmark(0.25, 0.5), 1e-7);
  const RodLoads loads = TipLoads(rod, 1.0);
  ASSERT_EQ(integrator.Initialize(rod.UndeformedState(), RodLoads::None(rod.NodeCount())),
            Status::kOk);
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(50, [&] { status = integrator.Step(loads); }), 0);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(integrator.last_stats().iterations, 1);
}

}  // namespace
}  // namespace cosmems
