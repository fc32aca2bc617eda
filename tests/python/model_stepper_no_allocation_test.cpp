#include <gtest/gtest.h>

#include <Eigen/Core>
#include <memory>

#include "allocation_counter.hpp"
#include "cosmems/scene/scene_loader.hpp"
#include "model_stepper.hpp"

namespace cosmems {
namespace {

// The step a Python loop calls (cosmems.Stepper.step): the load converted from SI, the state
// re-read after writes through its arrays, and the integrator's step, all without the heap.
TEST(NoAllocationTest, PythonStepperStepsAllocateNothing) {
  const std::shared_ptr<const python::SceneModel> model =
      std::make_shared<const python::SceneModel>(LoadScene("cantilever"));
  python::ModelStepper stepper(model, 1e-7, GeneralizedAlphaParameters::Newmark(0.25, 0.5),
                               {1e3, 1e-9});
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(model->size());
  ASSERT_EQ(stepper.Initialize(zero, zero, zero), Status::kOk);
  const Eigen::VectorXd f = Eigen::VectorXd::Constant(model->size(), 1e-9);
  Status status = Status::kOk;
  EXPECT_EQ(test::AllocationsDuring(100, [&] { status = stepper.Step(f); }), 0);
  EXPECT_EQ(status, Status::kOk);
  EXPECT_GT(stepper.displacement().norm(), 0.0);
}

}  // namespace
}  // namespace cosmems
