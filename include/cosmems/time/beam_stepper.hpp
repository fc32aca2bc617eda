#pragma once

#include <Eigen/Core>

#include "cosmems/beam/output_point.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

/// One stepping interface for every time path of a beam's reduced model M a + C v + K d + r(d)
/// = P s: the full-order Newmark family (the linear fast path, or Newton with a nonlinear force)
/// and modal propagation (exact, or with the force held over each step). Loads are amplitudes s
/// of the load patterns P (n x m) the stepper was built with, varying linearly over a step.
/// Everything in internal units. MakeBeamStepper (analysis/beam_stepper_factory.hpp) builds one
/// for a path; RunTransient and ProbedPhysics march with it. Step() allocates nothing.
class BeamStepper {
 public:
  virtual ~BeamStepper() = default;

  /// The state d0, v0 under the load amplitudes s0 at t = 0.
  virtual Status Initialize(const Eigen::VectorXd& d0, const Eigen::VectorXd& v0,
                            const Eigen::VectorXd& s0) = 0;
  /// Advances one step to the load amplitudes s_next. On failure the state stays at the step's
  /// start and the status says why.
  [[nodiscard]] virtual Status Step(const Eigen::VectorXd& s_next) = 0;
  /// Sets the output point Watched() reads (set-up: allocates).
  virtual void Watch(const OutputPoint& point) = 0;
  /// uy [m] at the watched point now: what a run records each step, which a modal path forms
  /// from its coordinates without forming the whole displacement.
  virtual double Watched() const = 0;
  /// The whole displacement (a modal path forms it here; allocates nothing).
  virtual const Eigen::VectorXd& displacement() const = 0;
  virtual double time() const = 0;
  /// What the last step cost (zero on the linear paths, which have no Newton).
  virtual const NewtonStats& last_stats() const = 0;
  /// Drops a Newton factor kept from earlier steps, where the caller knows the matrix has jumped
  /// since (a probe's spring coming on). The paths that keep none ignore it.
  virtual void ForgetFactor() {}
};

}  // namespace cosmems
