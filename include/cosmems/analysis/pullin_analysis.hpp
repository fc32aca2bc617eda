#pragma once

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <utility>

#include "cosmems/analysis/beam_field.hpp"
#include "cosmems/analysis/fold_search.hpp"
#include "cosmems/analysis/pullin_options.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/surface/gap_force.hpp"
#include "cosmems/surface/gap_pressures.hpp"
#include "cosmems/time/newton_driver.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

struct PullInResult {
  Status status = Status::kOk;
  Instability instability = Instability::kLimitPoint;  ///< how the stable path ends
  double scale = 0.0;            ///< the pressure's scale at the fold (V^2 for electrostatics)
  double voltage_v = 0.0;        ///< the pull-in voltage
  double travel_m = 0.0;         ///< deflection at control_x at pull-in (toward the substrate)
  double displacement_m = 0.0;   ///< largest deflection of the last stable state computed
  Eigen::VectorXd displacement;  ///< that state (reduced, internal units)
  int solves = 0;
  int iterations = 0;
};

/// The equilibrium path of a structure (a BeamModel or a FrameModel) pulled by a scaled force
/// under displacement control: at travel s (a fraction of the gap) the deflection at the control
/// point is -s gap, and the force's scale lambda is the unknown that holds it there:
///   K d + r(d) + lambda r_1(d) = 0,   e^T d = -s gap,
/// r_1 the `pulling` force (a gap pressure: the electrostatic one at 1 V, so that lambda = V^2; or
/// a surface force, lambda its multiple) and r any other nonlinear force (stretching, surface
/// forces). Newton on the bordered system, solved with two solves of the stiffness part J = K +
/// dr/dd + lambda dr_1/dd: J a = -R, J b = r_1, d lambda = (e^T a + c) / e^T b. The bordered matrix
/// stays regular through the fold where J turns singular, and J is positive definite on the stable
/// side, where FindFold keeps the solves. d lambda / ds = gap / e^T b.
template <class Model, class Pulling>
class FoldPath : private PlainNewtonScheme {
 public:
  /// `control`: the deflection [m] held at -s gap; `gap` [m] scales the travel s.
  FoldPath(const Model& model, Pulling pulling, OutputPoint control, double gap,
           const NewtonOptions& newton, NonlinearForce* other)
      : model_(model),
        pulling_(std::move(pulling)),
        other_(other),
        control_(std::move(control)),
        gap_(gap),
        newton_(newton) {
    const int n = model.FreeDofCount();
    const int w = model.Stiffness().bandwidth();
    other_tangent_ = ForceTangent(n, w);
    pulling_tangent_ = ForceTangent(n, w);
    jacobian_ = SymmetricBandMatrix(n, w);
    for (Eigen::VectorXd* v : {&d_, &accepted_, &rate_, &kd_, &r_, &r1_, &residual_, &a_, &b_}) {
      v->setZero(n);
    }
  }

  Status Solve(double s, double& lambda, double& slope) {
    d_ = accepted_ + (s - s_) * rate_;
    lambda_ = accepted_lambda_ + (s - s_) * accepted_slope_;
    target_ = -s * gap_;
    const Status status = newton_.Solve(*this, std::numeric_limits<double>::quiet_NaN());
    if (status != Status::kOk) return status;
    lambda = lambda_;
    slope = trial_slope_;
    trial_s_ = s;
    return Status::kOk;
  }

  void Accept() {
    s_ = trial_s_;
    accepted_ = d_;
    accepted_lambda_ = lambda_;
    accepted_slope_ = trial_slope_;
    rate_ = -trial_slope_ * b_;
  }

  const Eigen::VectorXd& accepted() const { return accepted_; }
  /// The scale lambda that holds the accepted state.
  double accepted_load() const { return accepted_lambda_; }
  /// What the solves along the path cost.
  const NewtonStats& stats() const { return newton_.stats(); }

 private:
  friend class NewtonDriver;

  // NewtonDriver's scheme on the bordered system. R = K d + r(d) + lambda r_1(d) and both
  // tangents; false outside a force's domain. The travel held is the side condition.
  bool Evaluate(NewtonResidual& out) {
    r_.setZero();
    r1_.setZero();
    other_tangent_.Clear();
    pulling_tangent_.Clear();
    if (other_ && !other_->Evaluate(d_, r_, other_tangent_)) return false;
    if (!pulling_.Evaluate(d_, r1_, pulling_tangent_)) return false;
    model_.Stiffness().Multiply(d_, kd_);
    residual_ = kd_ + r_ + lambda_ * r1_;
    if (!residual_.allFinite()) return false;
    c_ = control_.Evaluate(d_) - target_;
    out.norm = residual_.norm();
    out.reference = kd_.norm() + r_.norm() + std::abs(lambda_) * r1_.norm();
    out.side_conditions_met = std::abs(c_) <= newton_.options().residual_tolerance * gap_;
    return true;
  }
  // a_ serves as the bound's work vector: the Newton step overwrites it.
  double RoundOff() { return model_.Stiffness().ProductRoundOff(d_, a_); }

  // J = K + dr/dd + lambda dr_1/dd, factored; b solves J b = r_1.
  Status FactorAndSolveLoad() {
    jacobian_.mutable_data() = model_.Stiffness().data() + other_tangent_.band().data() +
                               lambda_ * pulling_tangent_.band().data();
    const Status status = factor_.Compute(jacobian_, other_tangent_.rank_one_scale(),
                                          other_tangent_.rank_one_vector());
    if (status != Status::kOk) return status;
    b_ = r1_;
    factor_.SolveInPlace(b_);
    eb_ = control_.Evaluate(b_);
    return Status::kOk;
  }
  // Only a solved state that is not definite lies past the stable path; an iterate on the way
  // there that is not tells nothing of it.
  NewtonFactor Factor(double /*shift*/) {
    NewtonFactor out;
    if (FactorAndSolveLoad() != Status::kOk) {
      out.status = Status::kNotConverged;
      return out;
    }
    a_ = -residual_;
    factor_.SolveInPlace(a_);
    return out;
  }
  // d lambda = (e^T a + c) / e^T b; no increment test (the bordered system converges on both
  // of its residuals).
  NewtonCorrection Update() {
    const double dlambda = (control_.Evaluate(a_) + c_) / eb_;
    d_ += a_ - dlambda * b_;
    lambda_ += dlambda;
    return {};
  }
  // The converged state's slope d lambda / ds = gap / e^T b; a state not definite is past the
  // fold.
  Status Finish() {
    const Status status = FactorAndSolveLoad();
    if (status != Status::kOk) return status;
    trial_slope_ = gap_ / eb_;
    return Status::kOk;
  }

  const Model& model_;
  Pulling pulling_;
  NonlinearForce* other_;
  OutputPoint control_;
  double gap_;  ///< m, as the control point measures deflections
  NewtonDriver newton_;
  ForceTangent other_tangent_, pulling_tangent_;
  SymmetricBandMatrix jacobian_;
  BandRankOneCholesky factor_;
  Eigen::VectorXd d_, accepted_, rate_, kd_, r_, r1_, residual_, a_, b_;
  double lambda_ = 0.0, accepted_lambda_ = 0.0, accepted_slope_ = 0.0, trial_slope_ = 0.0;
  double s_ = 0.0, trial_s_ = 0.0;
  double target_ = 0.0, c_ = 0.0, eb_ = 0.0;  ///< the travel held, its residual, e^T b
};

/// The end of a FoldPath's stable part (FindFold): its scale at the fold, with `voltage_v` the
/// square root of that scale (the voltage for the electrostatic pressure at 1 V), the travel [m]
/// at the control point and the last stable state; displacement_m is the caller's to fill.
template <class Path>
PullInResult TraceFold(Path& path, const FoldOptions& options, double gap) {
  const FoldPoint fold = FindFold(path, options);
  PullInResult out;
  out.scale = fold.load;
  out.status = fold.status;
  out.instability = fold.instability;
  out.solves = fold.solves;
  out.iterations = path.stats().iterations;
  out.displacement = path.accepted();
  if (fold.status != Status::kOk) return out;
  out.voltage_v = std::sqrt(fold.load);
  out.travel_m = fold.travel * gap;
  return out;
}

/// The fold of a beam pulled by a gap pressure over options.electrode, the travel held at
/// options.control_x. `options.fringing` is the electrostatic pressure's business and unused here.
template <int Dim, typename Pressure>
PullInResult SolveFold(const BeamModel<Dim>& model, Pressure pressure, const PullInOptions& options,
                       NonlinearForce* other = nullptr) {
  FoldPath<BeamModel<Dim>, GapForce<Dim, Pressure>> path(
      model, GapForce<Dim, Pressure>(model, pressure, options.electrode),
      OutputPoint::DeflectionAt(model, options.control_x), options.electrode.gap, options.newton,
      other);
  PullInResult out = TraceFold(path, options.fold, options.electrode.gap);
  if (out.status == Status::kOk) {
    out.displacement_m = BeamField<Dim>(model, out.displacement).MaxDeflectionTowardSubstrate();
  }
  return out;
}

/// The pull-in voltage of a beam over an electrode (options.electrode, with or without fringing
/// fields). `other` adds the forces the scene declares besides the electrostatic one.
template <int Dim>
PullInResult SolvePullIn(const BeamModel<Dim>& model, const PullInOptions& options,
                         NonlinearForce* other = nullptr) {
  const double width = model.description().elements[0].section.width;
  return SolveFold(model, ElectrostaticPressure{1.0, width, options.fringing}, options, other);
}

}  // namespace cosmems
