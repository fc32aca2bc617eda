#pragma once

#include <Eigen/Core>
#include <type_traits>
#include <utility>

#include "cosmems/time/beam_stepper.hpp"

namespace cosmems {

class NonlinearNewmarkIntegrator;

/// A Newmark-family integrator (LinearNewmarkIntegrator, NonlinearNewmarkIntegrator) as a
/// BeamStepper: the load f = P s formed for it each step.
template <typename Integrator>
class NewmarkStepper final : public BeamStepper {
 public:
  template <typename... Args>
  explicit NewmarkStepper(Eigen::MatrixXd patterns, Args&&... args)
      : patterns_(std::move(patterns)),
        integrator_(std::forward<Args>(args)...),
        f_(Eigen::VectorXd::Zero(patterns_.rows())) {}

  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& s0) override {
    f_.noalias() = patterns_ * s0;
    return integrator_.Initialize(d0, v0, f_);
  }
  [[nodiscard]] Status Step(const Eigen::VectorXd& s_next) override {
    f_.noalias() = patterns_ * s_next;
    return integrator_.Step(f_);
  }
  void Watch(const OutputPoint& point) override { watched_ = point; }
  double Watched() const override { return watched_.Evaluate(integrator_.displacement()); }
  const Eigen::VectorXd& displacement() const override { return integrator_.displacement(); }
  double time() const override { return integrator_.time(); }
  const NewtonStats& last_stats() const override { return integrator_.last_stats(); }
  void ForgetFactor() override {
    if constexpr (std::is_same_v<Integrator, NonlinearNewmarkIntegrator>)
      integrator_.ForgetFactor();
  }

  Integrator& integrator() { return integrator_; }

 private:
  Eigen::MatrixXd patterns_;
  Integrator integrator_;
  Eigen::VectorXd f_;
  OutputPoint watched_;
};

}  // namespace cosmems
