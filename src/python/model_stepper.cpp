#include "model_stepper.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace cosmems::python {
namespace {

RayleighDamping Internal(RayleighDamping si, const UnitSystem& u) {
  return {si.mass * u.time, si.stiffness / u.time};
}

void RequireSize(const char* name, Eigen::Index size, int expected) {
  if (size != expected) {
    throw std::invalid_argument(std::string(name) + " has " + std::to_string(size) +
                                " entries; the model has " + std::to_string(expected) +
                                " degrees of freedom");
  }
}

}  // namespace

ModelStepper::ModelStepper(std::shared_ptr<const SceneModel> model, double time_step_s,
                           GeneralizedAlphaParameters parameters, RayleighDamping damping_si)
    : model_(std::move(model)),
      integrator_(model_->Mass(0), model_->Stiffness(), Internal(damping_si, model_->units()),
                  parameters, time_step_s / model_->units().time),
      load_factor_(model_->dof_scale() / (model_->units().force * model_->units().length)),
      f_(Eigen::VectorXd::Zero(model_->size())) {
  if (integrator_.info() != Status::kOk) {
    throw std::invalid_argument(std::string("the step's matrix cannot be factored: ") +
                                ToString(integrator_.info()));
  }
  CopyState();
}

Status ModelStepper::Initialize(const Eigen::VectorXd& d0_si, const Eigen::VectorXd& v0_si,
                                const Eigen::VectorXd& f0_si) {
  RequireSize("d0", d0_si.size(), model_->size());
  RequireSize("v0", v0_si.size(), model_->size());
  LoadFromSi(f0_si);
  const Eigen::VectorXd& scale = model_->dof_scale();
  const Eigen::VectorXd d0 = d0_si.cwiseQuotient(scale);
  const Eigen::VectorXd v0 = v0_si.cwiseQuotient(scale) * model_->units().time;
  const Status status = integrator_.Initialize(d0, v0, f_);
  if (status == Status::kOk) CopyState();
  return status;
}

Status ModelStepper::Step(const Eigen::Ref<const Eigen::VectorXd>& f_next_si) {
  // The state may have been written through its arrays since the last step.
  integrator_.SetState(d_, v_, a_, f_);
  LoadFromSi(f_next_si);
  const Status status = integrator_.Step(f_);
  if (status == Status::kOk) CopyState();
  return status;
}

void ModelStepper::CopyState() {
  d_ = integrator_.displacement();
  v_ = integrator_.velocity();
  a_ = integrator_.acceleration();
}

void ModelStepper::LoadFromSi(const Eigen::Ref<const Eigen::VectorXd>& f_si) {
  RequireSize("f", f_si.size(), model_->size());
  f_ = f_si.cwiseProduct(load_factor_);
}

}  // namespace cosmems::python
