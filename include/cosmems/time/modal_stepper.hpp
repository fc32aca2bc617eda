#pragma once

#include <Eigen/Core>
#include <utility>

#include "cosmems/time/beam_stepper.hpp"
#include "cosmems/time/modal_model.hpp"
#include "cosmems/time/modal_propagator.hpp"
#include "cosmems/time/nonlinear_modal_integrator.hpp"

namespace cosmems {

/// Exact modal propagation (ModalPropagator) as a BeamStepper: d = Phi q + R P s, formed only
/// where it is read, and the initial state fitted to the modes in the M_0 norm.
class ModalStepper final : public BeamStepper {
 public:
  /// `fit`: ModalModel::Fit of the model; `residual_loads`: R P (ModalModel::ResidualFlexibility).
  ModalStepper(const ModalModel& modal, const Eigen::MatrixXd& patterns, Eigen::MatrixXd fit,
               Eigen::MatrixXd residual_loads, double time_step)
      : propagator_(modal.coordinates, modal.shapes, patterns, residual_loads, time_step),
        shapes_(modal.shapes),
        fit_(std::move(fit)),
        residual_loads_(std::move(residual_loads)),
        d_(Eigen::VectorXd::Zero(modal.shapes.rows())),
        s_(Eigen::VectorXd::Zero(patterns.cols())) {}

  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& s0) override {
    s_ = s0;
    d_ = d0 - residual_loads_ * s0;
    propagator_.Initialize(fit_ * d_, fit_ * v0, s0);
    return Status::kOk;
  }
  [[nodiscard]] Status Step(const Eigen::VectorXd& s_next) override {
    s_ = s_next;
    return propagator_.Step(s_next);
  }
  // The point's functional on the modes and on the load amplitudes, formed once.
  void Watch(const OutputPoint& point) override {
    watched_shapes_ = point.Evaluate(shapes_).transpose();
    watched_static_ = point.Evaluate(residual_loads_).transpose();
  }
  double Watched() const override {
    return watched_shapes_.dot(propagator_.modal_displacement()) + watched_static_.dot(s_);
  }
  const Eigen::VectorXd& displacement() const override {
    propagator_.Displacement(d_);
    return d_;
  }
  double time() const override { return propagator_.time(); }
  const NewtonStats& last_stats() const override { return no_newton_; }

 private:
  ModalPropagator propagator_;
  Eigen::MatrixXd shapes_, fit_, residual_loads_;
  mutable Eigen::VectorXd d_;  // formed where it is read
  Eigen::VectorXd s_;
  Eigen::VectorXd watched_shapes_, watched_static_;  // [m] per modal coordinate, per amplitude
  NewtonStats no_newton_;                            // exact propagation: no Newton
};

/// Modal propagation with the nonlinear force held over each step (NonlinearModalIntegrator) as
/// a BeamStepper.
class NonlinearModalStepper final : public BeamStepper {
 public:
  template <typename... Args>
  explicit NonlinearModalStepper(Args&&... args) : integrator_(std::forward<Args>(args)...) {}

  Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                    const Eigen::VectorXd& s0) override {
    return integrator_.Initialize(d0, v0, s0);
  }
  [[nodiscard]] Status Step(const Eigen::VectorXd& s_next) override {
    return integrator_.Step(s_next);
  }
  void Watch(const OutputPoint& point) override { watched_ = point; }
  double Watched() const override { return watched_.Evaluate(integrator_.displacement()); }
  const Eigen::VectorXd& displacement() const override { return integrator_.displacement(); }
  double time() const override { return integrator_.time(); }
  const NewtonStats& last_stats() const override { return integrator_.last_stats(); }

 private:
  NonlinearModalIntegrator integrator_;
  OutputPoint watched_;
};

}  // namespace cosmems
