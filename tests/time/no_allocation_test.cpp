// Steps allocate nothing, counted by allocation_counter.cpp, which interposes malloc for this
// executable (built only without sanitizers).
#include <gtest/gtest.h>

#include "allocation_counter.hpp"
#include "cosmems/analysis/modal_reduction.hpp"
#include "cosmems/beam/stretching_force.hpp"
#include "cosmems/linalg/symmetric_band_pair.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/modal_model.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"
#include "test_beams.hpp"

namespace cosmems {
namespace {

TEST(NoAllocationTest, CounterSeesAllocations) {
  const long before = test::AllocationCount();
  Eigen::VectorXd v(100);
  v.setZero();
  EXPECT_GT(test::AllocationCount(), before);
}

class LinearStepTest : public ::testing::TestWithParam<SpdSolverKind> {};

TEST_P(LinearStepTest, NewmarkStepsAllocateNothing) {
  const BeamModel<3> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 1));
  const int n = model.FreeDofCount();
  LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {1e-3, 1e-4},
                                     GeneralizedAlphaParameters::FromSpectralRadius(0.8), 1e-3,
                                     GetParam());
  ASSERT_EQ(integrator.solver_kind(), GetParam());
  const Eigen::VectorXd f = Eigen::VectorXd::Constant(n, 1e-3);
  ASSERT_EQ(integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f),
            Status::kOk);
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(100, [&] { status = integrator.Step(f); }), 0);
  EXPECT_EQ(status, Status::kOk);
}

INSTANTIATE_TEST_SUITE_P(Solvers, LinearStepTest,
                         ::testing::Values(SpdSolverKind::kDense, SpdSolverKind::kBand,
                                           SpdSolverKind::kCholmod));

TEST(NoAllocationTest, ModalStepsAllocateNothing) {
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 1));
  LoadCase loads;
  loads.points.push_back(
      {test::kReferenceLength, Eigen::Vector3d(0, -1e-7, 0), Eigen::Vector3d::Zero()});
  const Eigen::MatrixXd pattern = AssembleLoads(model, loads);
  const ModalModel modal =
      MakeModalModel(model, SolveModal(model), DampingModel::QualityFactor(100));
  ModalPropagator propagator(modal.coordinates, modal.shapes, pattern,
                             modal.ResidualFlexibility(model, pattern), 1e-3);
  const int n = model.FreeDofCount();
  const Eigen::VectorXd s = Eigen::VectorXd::Ones(1);
  const Eigen::VectorXd q0 = Eigen::VectorXd::Zero(modal.shapes.cols());
  propagator.Initialize(q0, q0, s);
  Eigen::VectorXd d(n);
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(100,
                                    [&] {
                                      status = propagator.Step(s);
                                      propagator.Displacement(d);
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
}

// A hardening spring at the tip: a force of the kind later effects add, written without
// allocation as NonlinearForce requires.
class TipSpring : public NonlinearForce {
 public:
  explicit TipSpring(int dof) : dof_(dof) {}
  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    force[dof_] += 1e3 * d[dof_] * d[dof_] * d[dof_];
    tangent.band().Add(dof_, dof_, 3e3 * d[dof_] * d[dof_]);
    return true;
  }

 private:
  int dof_;
};

TEST(NoAllocationTest, NonlinearStepsAllocateNothing) {
  const BeamModel<2> model(MakeStructure(StructureKind::kCantilever, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 0));
  const int n = model.FreeDofCount();
  TipSpring spring(model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy));
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, spring,
                                        GeneralizedAlphaParameters::FromSpectralRadius(0.8), 0.01);
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  f[model.dofs().Reduced(model.NodeCount() - 1, NodalDof::kUy)] = -1e-3;
  ASSERT_EQ(integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f),
            Status::kOk);
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(50, [&] { status = integrator.Step(f); }), 0);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(integrator.last_stats().evaluations, 1);  // Newton really iterated
}

// The residual's paired band products, by a fixed kernel (11) and by the general loop (7).
TEST(NoAllocationTest, PairedBandProductsAllocateNothing) {
  for (int bw : {7, 11}) {
    SymmetricBandMatrix a(30, bw), b(30, bw);
    a.mutable_data().setConstant(1.0);
    b.mutable_data().setConstant(2.0);
    SymmetricBandPair pair(a, b);
    const Eigen::VectorXd x = Eigen::VectorXd::Ones(30);
    Eigen::VectorXd ax(30), bz(30);
    EXPECT_EQ(test::AllocationsDuring(10, [&] { pair.Multiply(x, x, ax, bz); }), 0) << bw;
    EXPECT_EQ(bz[15], 2.0 * (2 * bw + 1));  // an interior row: 2 bw + 1 entries of 2
  }
}

// Mid-plane stretching: a rank-one tangent part, renewed at every iteration on a band factor
// that is sometimes kept and sometimes made anew (both paths run within these steps).
TEST(NoAllocationTest, StretchingStepsAllocateNothing) {
  const BeamModel<2> model(MakeStructure(StructureKind::kBridge, test::kReferenceLength,
                                         test::Silicon(), test::ReferenceSection(), 20, 0));
  const int n = model.FreeDofCount();
  StretchingForce<2> force(model);
  const double dt = 2.3e-6 / 20 / model.units().time;
  NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), {}, force,
                                        GeneralizedAlphaParameters::Newmark(0.25, 0.5), dt);
  LoadCase loads;  // rings the bridge at half a thickness, where stretching matters
  loads.points.push_back(
      {test::kReferenceLength / 2, Eigen::Vector3d(0, -1e-4, 0), Eigen::Vector3d::Zero()});
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  ASSERT_EQ(integrator.Initialize(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n), f),
            Status::kOk);
  Status status = Status::kOk;
  int iterations = 0, factorizations = 0;
  EXPECT_EQ(test::AllocationsDuring(50,
                                    [&] {
                                      status = integrator.Step(f);
                                      iterations += integrator.last_stats().evaluations;
                                      factorizations += integrator.last_stats().factorizations;
                                    }),
            0);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(factorizations, 0);
  EXPECT_LT(factorizations, iterations - 50);  // some iterations kept the factor
}

}  // namespace
}  // namespace cosmems
