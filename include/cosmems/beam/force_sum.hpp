#pragma once

#include <Eigen/Core>
#include <vector>

#include "cosmems/beam/nonlinear_force.hpp"

namespace cosmems {

/// The sum of the nonlinear forces a scene declares, composed at run time: only those added are
/// evaluated. At most one of them may carry a rank-one tangent part (mid-plane stretching).
class ForceSum final : public NonlinearForce {
 public:
  void Add(NonlinearForce& force) { forces_.push_back(&force); }
  bool Empty() const { return forces_.empty(); }

  bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (NonlinearForce* f : forces_) {
      if (!f->Evaluate(d, force, tangent)) return false;
    }
    return true;
  }

  bool HasViscousPart() const override {
    for (const NonlinearForce* f : forces_) {
      if (f->HasViscousPart()) return true;
    }
    return false;
  }
  bool EvaluateViscous(const Eigen::VectorXd& d, const Eigen::VectorXd& v, double velocity_factor,
                       Eigen::VectorXd& force, ForceTangent& tangent) override {
    for (NonlinearForce* f : forces_) {
      if (!f->EvaluateViscous(d, v, velocity_factor, force, tangent)) return false;
    }
    return true;
  }

  bool Idle(const Eigen::VectorXd& d) const override {
    for (const NonlinearForce* f : forces_) {
      if (!f->Idle(d)) return false;
    }
    return true;
  }
  bool Settle(const Eigen::VectorXd& d) override {
    bool settled = true;
    for (NonlinearForce* f : forces_) settled = f->Settle(d) && settled;
    return settled;
  }
  void Commit(const Eigen::VectorXd& d) override {
    for (NonlinearForce* f : forces_) f->Commit(d);
  }
  void Revert() override {
    for (NonlinearForce* f : forces_) f->Revert();
  }
  void StartStep() override {
    for (NonlinearForce* f : forces_) f->StartStep();
  }
  void ProjectMotion(const Eigen::VectorXd& d, Eigen::VectorXd& v, Eigen::VectorXd& a) override {
    for (NonlinearForce* f : forces_) f->ProjectMotion(d, v, a);
  }
  bool LetsGo(const Eigen::VectorXd& start, const Eigen::VectorXd& predicted) const override {
    for (const NonlinearForce* f : forces_) {
      if (f->LetsGo(start, predicted)) return true;
    }
    return false;
  }

 private:
  std::vector<NonlinearForce*> forces_;
};

}  // namespace cosmems
