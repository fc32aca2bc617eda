#pragma once

#include <Eigen/Core>
#include <memory>

#include "cosmems/core/status.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/rayleigh_damping.hpp"
#include "scene_model.hpp"

namespace cosmems::python {

/// A linear Newmark-family integrator on a SceneModel, for a time loop written in Python: M a +
/// C v + K d = f with C = alpha M + beta K. Loads come in SI and are converted into a buffer of
/// its own. The state d, v, a (internal units) is three vectors of this object's own, which
/// Python sees as arrays without a copy and may write: they stay where they are for the
/// stepper's life and hold the current state after every call, so an array kept across steps
/// stays current (the integrator's own vectors swap with its scratch ones every step). Every
/// step copies them into the integrator, re-deriving its prepared products (a write there
/// bypasses it), and copies its new state back: passes over the vectors, no allocation.
class ModelStepper {
 public:
  /// `damping_si`: alpha [1/s] and beta [s]. Throws std::invalid_argument for a bad time step.
  ModelStepper(std::shared_ptr<const SceneModel> model, double time_step_s,
               GeneralizedAlphaParameters parameters, RayleighDamping damping_si);

  /// The state at t = 0 from d0 [m, rad], v0 [m/s, rad/s] and the load f0 [N, N m] there.
  Status Initialize(const Eigen::VectorXd& d0_si, const Eigen::VectorXd& v0_si,
                    const Eigen::VectorXd& f0_si);
  /// One step to the load f_next [N, N m]; allocates nothing. On failure the state stays.
  Status Step(const Eigen::Ref<const Eigen::VectorXd>& f_next_si);

  /// The state (internal units: S d is in m and rad), in buffers that never move.
  Eigen::VectorXd& displacement() { return d_; }
  Eigen::VectorXd& velocity() { return v_; }
  Eigen::VectorXd& acceleration() { return a_; }
  double time_s() const { return integrator_.time() * model_->units().time; }
  double time_step_s() const { return integrator_.time_step() * model_->units().time; }
  const SceneModel& model() const { return *model_; }

 private:
  // d_, v_, a_ from the integrator's state.
  void CopyState();
  // f [internal] from f [SI] into f_.
  void LoadFromSi(const Eigen::Ref<const Eigen::VectorXd>& f_si);

  std::shared_ptr<const SceneModel> model_;
  LinearNewmarkIntegrator integrator_;
  Eigen::VectorXd load_factor_;  ///< S / (F L), per degree of freedom
  Eigen::VectorXd f_;            ///< the last load, internal units
  Eigen::VectorXd d_, v_, a_;    ///< the state Python sees, internal units
};

}  // namespace cosmems::python
