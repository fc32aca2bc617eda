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
/// its own; the state d, v, a is the integrator's own vectors (internal units), which Python
/// sees as arrays without a copy and may write. Because a write there bypasses the integrator,
/// every step first re-derives the integrator's prepared products from the state (one pass over
/// the vectors, no allocation).
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

  /// The integrator's own state vectors (internal units: S d is in m and rad).
  Eigen::VectorXd& displacement() { return Own(integrator_.displacement()); }
  Eigen::VectorXd& velocity() { return Own(integrator_.velocity()); }
  Eigen::VectorXd& acceleration() { return Own(integrator_.acceleration()); }
  double time_s() const { return integrator_.time() * model_->units().time; }
  double time_step_s() const { return integrator_.time_step() * model_->units().time; }
  const SceneModel& model() const { return *model_; }

 private:
  // The integrator hands out const references to vectors it owns and this object owns it:
  // writing through them is writing this object's state.
  static Eigen::VectorXd& Own(const Eigen::VectorXd& x) { return const_cast<Eigen::VectorXd&>(x); }
  // f [internal] from f [SI] into f_.
  void LoadFromSi(const Eigen::Ref<const Eigen::VectorXd>& f_si);

  std::shared_ptr<const SceneModel> model_;
  LinearNewmarkIntegrator integrator_;
  Eigen::VectorXd load_factor_;  ///< S / (F L), per degree of freedom
  Eigen::VectorXd f_;            ///< the last load, internal units
};

}  // namespace cosmems::python
