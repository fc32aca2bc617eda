#pragma once

#include <Eigen/Core>

#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// dr/dd of a NonlinearForce: a part in the structure's band pattern plus at most one symmetric
/// rank-one part s u u^T. Mid-plane stretching needs the latter: its axial force depends on the
/// slope everywhere, so its tangent couples every pair of degrees of freedom, which a band
/// cannot hold but a rank-one term carries exactly (and Sherman-Morrison solves cheaply).
class ForceTangent {
 public:
  ForceTangent() = default;
  ForceTangent(int size, int bandwidth)
      : band_(size, bandwidth), rank_one_(Eigen::VectorXd::Zero(size)) {}

  /// Zeroes both parts and asks the forces for both; allocates nothing.
  void Clear() {
    band_.mutable_data().setZero();
    scale_ = 0.0;
    band_wanted_ = true;
  }
  /// Zeroes the rank-one part and tells the forces the band part is not wanted: a Newton
  /// iteration that solves with a kept factor uses the rank-one part alone, and assembling the
  /// band (the surface forces' quadrature of it, a pass over the whole band to clear it) costs
  /// as much as the force itself. A force may add band entries all the same: they are ignored.
  void ClearRankOne() {
    scale_ = 0.0;
    band_wanted_ = false;
  }
  /// Whether Evaluate() should add the band part (false after ClearRankOne()).
  bool band_wanted() const { return band_wanted_; }

  SymmetricBandMatrix& band() { return band_; }
  const SymmetricBandMatrix& band() const { return band_; }

  /// Sets the rank-one part to scale u u^T (u of the structure's size; allocates nothing).
  void SetRankOne(double scale, const Eigen::VectorXd& u) {
    scale_ = scale;
    rank_one_ = u;
  }
  double rank_one_scale() const { return scale_; }
  const Eigen::VectorXd& rank_one_vector() const { return rank_one_; }

  /// The whole tangent as a dense matrix (tests, small modal problems).
  Eigen::MatrixXd ToDense() const {
    Eigen::MatrixXd out = band_.ToDense();
    if (scale_ != 0.0) out += scale_ * rank_one_ * rank_one_.transpose();
    return out;
  }

 private:
  SymmetricBandMatrix band_;
  Eigen::VectorXd rank_one_;
  double scale_ = 0.0;
  bool band_wanted_ = true;
};

/// A displacement-dependent internal force r(d) with its consistent tangent dr/dd, added to a
/// linear structure: M a + C v + K d + r(d) = f. Geometric stiffening, stretching, contact and
/// surface forces implement it. Evaluate() runs inside Newton iterations: it must allocate
/// nothing, and it reports a state outside its domain by returning false (the step is then cut).
/// A force that also depends on the velocity, a gas film's damping, adds that part in
/// EvaluateViscous(), which the time integrators call beside Evaluate(); a state at rest has none,
/// so statics leave it out.
class NonlinearForce {
 public:
  virtual ~NonlinearForce() = default;

  /// Adds r(d) to `force` and dr/dd to `tangent` (the structure's band pattern, plus a rank-one
  /// part if the force needs one), both in the model's internal units. The band part may be
  /// left out where !tangent.band_wanted(); the rank-one part never: r and it must be the same
  /// either way.
  virtual bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force,
                        ForceTangent& tangent) = 0;

  /// Whether EvaluateViscous() adds anything: the integrators skip the velocity it needs when
  /// no force has a velocity-dependent part.
  virtual bool HasViscousPart() const { return false; }
  /// Adds the velocity-dependent part r_v(d, v) to `force` and dr_v/dd + velocity_factor dr_v/dv
  /// to `tangent`, velocity_factor being dv/dd along the step (gamma / (beta h) for Newmark).
  /// Allocates nothing. A force without one keeps this default.
  virtual bool EvaluateViscous(const Eigen::VectorXd& /*d*/, const Eigen::VectorXd& /*v*/,
                               double /*velocity_factor*/, Eigen::VectorXd& /*force*/,
                               ForceTangent& /*tangent*/) {
    return true;
  }

  /// Whether the force is idle at d: r (its velocity-dependent part included) and its tangent
  /// vanish in a neighbourhood of d, and Settle() and ProjectMotion() would change nothing there
  /// (a contact whose every point is clear of the substrate, unstuck and unpushed). A step whose
  /// start and end are both idle is then the linear structure's, which the integrators solve
  /// without Newton. The default, never idle, is always safe. Allocates nothing.
  virtual bool Idle(const Eigen::VectorXd& /*d*/) const { return false; }

  // A force with an internal state (contact multipliers, stuck nodes) takes part in the solvers'
  // protocol below; a plain force r(d) keeps the defaults.

  /// Newton has converged on d. A force whose state must change there (a multiplier update that
  /// cuts a penetration, a node that peels off) changes it and returns false: the solver then
  /// iterates again from d. Allocates nothing.
  virtual bool Settle(const Eigen::VectorXd& /*d*/) { return true; }
  /// The solver accepted d (a time step, a load step): the state becomes the one Revert() returns
  /// to, and events are counted.
  virtual void Commit(const Eigen::VectorXd& /*d*/) {}
  /// The solver abandoned the states Settle() reached since the last Commit().
  virtual void Revert() {}
  /// A time step starts from the committed state (after Commit(), or after Revert() when a step
  /// is retried in halves). A force whose state can move toward that state's balance before
  /// Newton runs moves it here (a contact's multipliers take the committed reactions: one
  /// multiplier update between steps, so a contact pressed steadily rarely needs one inside a
  /// step). Revert() goes back to the state before it. NonlinearNewmarkIntegrator calls it;
  /// statics do not, nor does the modal path, whose forces are held over a step (with it, a step
  /// of the resonator's shuttle pressed onto the substrate failed). Allocates nothing.
  virtual void StartStep() {}
  /// Whether a contact this force holds at `start`, a time step's start, lets go at
  /// `predicted`, the integrator's extrapolation of the last step's motion to the step's end.
  /// That motion is what the contact stopped: a structure the probe began to push moved into
  /// the spring over the last step, and its velocity carries the prediction off it, where the
  /// factor Newton keeps (formed with the spring) no longer fits the forces and a fresh one
  /// (without it) overshoots back into the spring. NonlinearNewmarkIntegrator then starts Newton
  /// from the step's start, where the contact holds. The default, never, keeps the prediction.
  /// Allocates nothing.
  virtual bool LetsGo(const Eigen::VectorXd& /*start*/,
                      const Eigen::VectorXd& /*predicted*/) const {
    return false;
  }
  /// A time step ended at d with velocity v and acceleration a: a constraint removes the motion
  /// it forbids (a node driven onto the substrate stops there: an inelastic impact). Allocates
  /// nothing.
  virtual void ProjectMotion(const Eigen::VectorXd& /*d*/, Eigen::VectorXd& /*v*/,
                             Eigen::VectorXd& /*a*/) {}
};

}  // namespace cosmems
