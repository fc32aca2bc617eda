#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/rod/block_tridiagonal_system.hpp"
#include "cosmems/rod/cosserat_options.hpp"
#include "cosmems/rod/cosserat_rod.hpp"
#include "cosmems/rod/rod_loads.hpp"
#include "cosmems/rod/rod_state.hpp"
#include "cosmems/rod/so3.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/newton_driver.hpp"
#include "cosmems/time/newton_options.hpp"
#include "cosmems/time/newton_stats.hpp"

namespace cosmems {

/// Transient motion of a Cosserat rod by the Newmark family on the rotation group, in the
/// generalised-alpha form of Arnold & Bruls (2007) for Lie groups. Per node, with v the velocity
/// (spatial for translations, the material angular velocity W for rotations), vdot the true
/// acceleration and a a pseudo-acceleration (A and Wdot for rotations):
///   u_(n+1) = u_n + h v_n + h^2 ((1/2 - beta) a_n + beta a_(n+1)),
///   R_(n+1) = R_n exp(Theta^),  Theta = h W_n + h^2 ((1/2 - beta) A_n + beta A_(n+1)),
///   v_(n+1) = v_n + h ((1 - gamma) a_n + gamma a_(n+1)),
///   (1 - alpha_m) a_(n+1) + alpha_m a_n = (1 - alpha_f) vdot_(n+1) + alpha_f vdot_n,
/// and the balance holds at t_(n+1) itself: m vdot + f_int = f (translations, lumped rho A) and
/// R (J Wdot + W x J W) + m_int = m (rotations, lumped rho I about the directors). With
/// alpha_m = alpha_f = 0, a = vdot and this is the Newmark family on the group (Simo & Vu-Quoc
/// 1988, material form); GeneralizedAlphaParameters::FromSpectralRadius(rho_inf) gives the
/// second-order members that damp the high frequencies (for linear problems the same spectral
/// properties as the Chung-Hulbert form the linear integrators use).
///
/// Which member: the rod's axial, shear and rotary-inertia modes lie at MHz and beyond, where
/// h omega >> 1 at any step that resolves the bending. Average acceleration (rho_inf = 1) leaves
/// them undamped, and in large-amplitude motion the nonlinear coupling pumps energy into them
/// (the instability of the trapezoidal rule in nonlinear elastodynamics, Simo & Tarnow 1992):
/// released from PL^2/EI = 2 the reference cantilever's element forces reach 30 times the load
/// within two periods and its step matrix turns indefinite. rho_inf = 0.9 takes that energy out
/// as it comes (the amplitudes at h omega >> 1 shrink by 0.9 a step) and leaves the resolved
/// modes second-order accurate. Average acceleration still conserves energy in the linear,
/// small-amplitude limit.
///
/// Newton on (u_(n+1), R_(n+1)) with rotations updated multiplicatively. Its matrix holds the
/// exact stiffness and load stiffness and the symmetric part of the inertia's linearisation,
///   R (c J + gamma / (beta h) ([W]x J - [J W]x)) J_r^-1(Theta) R^T,
///   c = (1 - alpha_m) / ((1 - alpha_f) beta h^2).
/// The skew part (gyroscopic and frame-transport terms) is left out to keep the factorisation
/// symmetric; relative to c J it is of order h |W|, the angle a node turns in one step, so the
/// iterations contract by that factor instead of quadratically.
///
/// A step whose iterations fail is retried as two half steps, recursively up to
/// NewtonOptions::max_cuts; on final failure the state stays at the start of the step and the
/// status says why. Implicit members only (beta > 0). Steps allocate nothing.
class CosseratNewmarkIntegrator : private PlainNewtonScheme {
 public:
  CosseratNewmarkIntegrator(const CosseratRod& rod, GeneralizedAlphaParameters parameters,
                            double time_step, NewtonOptions options = RodNewtonOptions())
      : rod_(rod),
        p_(parameters),
        dt_(time_step / rod.units().time),
        newton_(options),
        state_(rod.UndeformedState()),
        new_state_(state_),
        trial_state_(state_),
        saved_state_(state_),
        system_(rod.MakeSystem()),
        correction_(3, rod.NodeCount()),
        theta_(3, rod.NodeCount()),
        kinematics_(rod.MakeKinematics()) {
    RequirePositive("time_step", time_step);
    RequireWithin("beta", p_.beta, 1e-6, 1.0);
    RequireWithin("gamma", p_.gamma, 0.5, 1.5);
    RequireWithin("alpha_m", p_.alpha_m, -1.0, 0.5);
    RequireWithin("alpha_f", p_.alpha_f, 0.0, 0.5);
    ValidateNewtonOptions(options);
    const int nodes = rod.NodeCount();
    for (Motion* m : {&motion_, &motion_new_, &motion_save_}) m->Resize(nodes);
    for (RodLoads* loads : {&start_loads_, &target_loads_, &loads_}) {
      *loads = RodLoads::None(nodes);
    }
    for (Eigen::VectorXd* v : {&residual_, &increment_}) v->setZero(rod.DofCount());
  }

  /// Starts at `state` (internal units, e.g. a static solution) at rest under `loads` (SI): the
  /// initial accelerations balance the loads against the internal forces (and the
  /// pseudo-accelerations start equal to them).
  Status Initialize(const RodState& state, const RodLoads& loads) {
    state_ = state;
    rod_.ToInternal(loads, start_loads_);
    time_ = 0.0;
    motion_.v.setZero();
    motion_.w.setZero();
    rod_.InternalForces(state_, residual_, kinematics_);
    rod_.SubtractLoads(state_, start_loads_, residual_, nullptr);
    rod_.ClearSupported(residual_);
    if (!residual_.allFinite()) return Status::kNonFinite;
    for (int i = 0; i < rod_.NodeCount(); ++i) {
      motion_.a.col(i) = -residual_.segment<3>(6 * i) / rod_.NodeMass(i);
      // The spatial angular acceleration solves (R J R^T) alpha = -r_theta on the free
      // components (a support holds components of the spatial rotation).
      const Eigen::Matrix3d r = state_.Rotation(i).toRotationMatrix();
      Eigen::Matrix3d inertia = r * rod_.NodeRotaryInertia(i).asDiagonal() * r.transpose();
      Eigen::Vector3d rhs = -residual_.segment<3>(6 * i + 3);
      for (int k = 0; k < 3; ++k) {
        if (rod_.FixedMask(i) & (1u << (3 + k))) {
          inertia.row(k).setZero();
          inertia.col(k).setZero();
          inertia(k, k) = 1.0;
        }
      }
      motion_.alpha.col(i) = r.transpose() * inertia.partialPivLu().solve(rhs);
    }
    motion_.vdot = motion_.a;  // the pseudo-accelerations start at the true ones
    motion_.wdot = motion_.alpha;
    return motion_.alpha.allFinite() && motion_.a.allFinite() ? Status::kOk : Status::kNonFinite;
  }

  /// Advances by the time step to the loads `loads_next` (SI), applied linearly over the step.
  [[nodiscard]] Status Step(const RodLoads& loads_next) {
    assert(loads_next.dead_forces.cols() == rod_.NodeCount());
    rod_.ToInternal(loads_next, target_loads_);
    saved_state_ = state_;
    motion_save_.CopyFrom(motion_);
    const double time_save = time_;
    newton_.stats() = {};
    // A failed part of the step is cut in halves; the state at its start is saved above and no
    // force has a state to revert.
    const Status status = newton_.AdvanceInHalves(
        [this](double from, double to, int) { return Substep(to - from, to); }, [] {}, [] {});
    if (status == Status::kOk) {
      std::swap(start_loads_, target_loads_);
    } else {
      std::swap(state_, saved_state_);
      motion_.Swap(motion_save_);
      time_ = time_save;
    }
    return status;
  }

  const CosseratRod& rod() const { return rod_; }
  const RodState& state() const { return state_; }
  /// Time since Initialize() [s].
  double time() const { return time_ * rod_.units().time; }
  /// Velocity of the last node [m/s].
  Eigen::Vector3d TipVelocity() const {
    const UnitSystem& u = rod_.units();
    return (u.length / u.time) * motion_.v.col(rod_.NodeCount() - 1);
  }
  /// Kinetic energy (1/2) sum (m |v|^2 + W . J W) [J].
  double KineticEnergy() const {
    double t = 0.0;
    for (int i = 0; i < rod_.NodeCount(); ++i) {
      t += rod_.NodeMass(i) * motion_.v.col(i).squaredNorm() +
           motion_.w.col(i).dot(rod_.NodeRotaryInertia(i).cwiseProduct(motion_.w.col(i)));
    }
    return 0.5 * t * rod_.units().force * rod_.units().length;
  }
  /// Strain energy [J].
  double StrainEnergy() const {
    return rod_.StrainEnergy(state_) * rod_.units().force * rod_.units().length;
  }
  /// What the last step cost (all its sub-steps).
  const NewtonStats& last_stats() const { return newton_.stats(); }

 private:
  friend class NewtonDriver;

  // One Newmark step of `fraction` dt ending at the fraction `to` of the step.
  Status Substep(double fraction, double to) {
    const double h = fraction * dt_;
    RodLoads::Interpolate(start_loads_, target_loads_, to, loads_);
    // Predictor: constant velocity, u + h v and R exp(h W^) (= exp(h (R W)^) R), applied as a
    // Newton update so that the chords turn with their elements instead of stretching. The
    // accelerations are left out: those of the stiff axial and shear modes (h omega ~ 10) are
    // large and alternate from step to step, and extrapolating them predicts axial forces that
    // can make the step's matrix indefinite. Released from PL^2/EI = 2 (rho_inf = 0.9, 100 steps
    // a period, 50 elements): 3.0 iterations a step without them, 5.6 with, most steps cut.
    for (int i = 0; i < rod_.NodeCount(); ++i) {
      increment_.segment<3>(6 * i) = h * motion_.v.col(i);
      increment_.segment<3>(6 * i + 3) = state_.Rotation(i) * (h * motion_.w.col(i));
    }
    rod_.Retract(state_, increment_, 1.0, new_state_, correction_);
    h_ = h;
    return newton_.Solve(*this, std::numeric_limits<double>::quiet_NaN());
  }

  // NewtonDriver's scheme, on the state at t_(n+1).
  bool Evaluate(NewtonResidual& out) {
    out.reference = Evaluate(h_, true);
    out.norm = residual_.norm();
    kinematics_stale_ = false;
    return true;
  }
  NewtonFactor Factor(double /*shift*/) {
    AssembleMatrix(h_);
    NewtonFactor out;
    out.status = system_.Factorize();
    if (out.status != Status::kOk) return out;
    increment_ = -residual_;
    system_.SolveInPlace(increment_);
    return out;
  }
  // The update that moves each chord with its element's rotation (see CosseratRod::Retract):
  // the axial stiffness outweighs the inertia in this matrix by far (EA/h against
  // rho A h / (beta dt^2)), so the stretch of a plain update would cost iterations here too.
  NewtonCorrection Update() {
    std::swap(new_state_, trial_state_);
    rod_.Retract(trial_state_, increment_, 1.0, new_state_, correction_);
    kinematics_stale_ = true;
    NewtonCorrection out;
    out.size = increment_.norm();
    out.iterate = new_state_.Size();
    return out;
  }
  Status Finish() { return Accept(h_, kinematics_stale_); }

  // The coefficients of the step of length h.
  struct Coefficients {
    double c0, c1, keep;  // a_(n+1) = c0 (du - h v_n) - keep a_n; dv/du = c1
    double true_weight, old_weight, old_true_weight;  // vdot_(n+1) from a_(n+1), a_n, vdot_n
    double inertia;                                   // d vdot_(n+1) / d u_(n+1)
  };
  Coefficients CoefficientsFor(double h) const {
    Coefficients c;
    c.c0 = 1.0 / (p_.beta * h * h);
    c.c1 = p_.gamma / (p_.beta * h);
    c.keep = 0.5 / p_.beta - 1.0;
    c.true_weight = (1.0 - p_.alpha_m) / (1.0 - p_.alpha_f);
    c.old_weight = p_.alpha_m / (1.0 - p_.alpha_f);
    c.old_true_weight = p_.alpha_f / (1.0 - p_.alpha_f);
    c.inertia = c.true_weight * c.c0;
    return c;
  }

  // The kinematics of new_state_ (motion_new_.v ... motion_new_.wdot, and the increments theta_)
  // and, when `full`, the residual with its reference size (returned).
  double Evaluate(double h, bool full) {
    const Coefficients c = CoefficientsFor(h);
    const double gamma = p_.gamma;
    double size = 0.0;
    if (full) {
      size = rod_.InternalForces(new_state_, residual_, kinematics_);
      size += rod_.SubtractLoads(new_state_, loads_, residual_, &system_);
    }
    double inertia2 = 0.0;
    for (int i = 0; i < rod_.NodeCount(); ++i) {
      motion_new_.a.col(i) = c.c0 * (new_state_.displacement.col(i) - state_.displacement.col(i) -
                                     h * motion_.v.col(i)) -
                             c.keep * motion_.a.col(i);
      motion_new_.v.col(i) =
          motion_.v.col(i) + h * ((1.0 - gamma) * motion_.a.col(i) + gamma * motion_new_.a.col(i));
      motion_new_.vdot.col(i) = c.true_weight * motion_new_.a.col(i) +
                                c.old_weight * motion_.a.col(i) -
                                c.old_true_weight * motion_.vdot.col(i);
      const Eigen::Quaterniond q = new_state_.Rotation(i);
      theta_.col(i) = QuaternionLog(state_.Rotation(i).conjugate() * q);
      motion_new_.alpha.col(i) =
          c.c0 * (theta_.col(i) - h * motion_.w.col(i)) - c.keep * motion_.alpha.col(i);
      motion_new_.w.col(i) = motion_.w.col(i) + h * ((1.0 - gamma) * motion_.alpha.col(i) +
                                                     gamma * motion_new_.alpha.col(i));
      motion_new_.wdot.col(i) = c.true_weight * motion_new_.alpha.col(i) +
                                c.old_weight * motion_.alpha.col(i) -
                                c.old_true_weight * motion_.wdot.col(i);
      if (!full) continue;
      const Eigen::Vector3d& j = rod_.NodeRotaryInertia(i);
      const Eigen::Vector3d torque =
          j.cwiseProduct(motion_new_.wdot.col(i)) +
          motion_new_.w.col(i).cross(j.cwiseProduct(motion_new_.w.col(i)));
      residual_.segment<3>(6 * i) += rod_.NodeMass(i) * motion_new_.vdot.col(i);
      residual_.segment<3>(6 * i + 3) += q * torque;
      inertia2 += rod_.NodeMass(i) * rod_.NodeMass(i) * motion_new_.vdot.col(i).squaredNorm() +
                  torque.squaredNorm();
    }
    if (full) rod_.ClearSupported(residual_);
    return size + std::sqrt(inertia2);
  }

  // The Newton matrix at new_state_ after Evaluate(h, true): the elements' tangent, the inertia
  // and the load stiffness (already set by Evaluate).
  void AssembleMatrix(double h) {
    const Coefficients c = CoefficientsFor(h);
    rod_.InternalTangent(kinematics_, system_);
    for (int i = 0; i < rod_.NodeCount(); ++i) {
      const Eigen::Vector3d& j = rod_.NodeRotaryInertia(i);
      const Eigen::Vector3d jw = j.cwiseProduct(motion_new_.w.col(i));
      const Eigen::Matrix3d r = new_state_.Rotation(i).toRotationMatrix();
      const Eigen::Matrix3d q_matrix =
          Eigen::Matrix3d(c.inertia * j.asDiagonal()) +
          c.c1 * (Skew(motion_new_.w.col(i)) * j.asDiagonal() - Skew(jw));
      const Eigen::Matrix3d k = r * q_matrix * LeftJacobianInverse(-theta_.col(i)) * r.transpose();
      BlockTridiagonalSystem::Block& d = system_.Diagonal(i);
      d.topLeftCorner<3, 3>().diagonal().array() += c.inertia * rod_.NodeMass(i);
      d.bottomRightCorner<3, 3>() += 0.5 * (k + k.transpose());
    }
  }

  Status Accept(double h, bool kinematics_stale) {
    if (kinematics_stale) Evaluate(h, false);
    std::swap(state_, new_state_);
    motion_.Swap(motion_new_);
    time_ += h;
    return Status::kOk;
  }

  const CosseratRod& rod_;
  GeneralizedAlphaParameters p_;
  double dt_;  // internal units
  NewtonDriver newton_;
  double time_ = 0.0;
  double h_ = 0.0;                 // the sub-step being solved
  bool kinematics_stale_ = false;  // new_state_ moved since its kinematics were formed
  RodState state_, new_state_, trial_state_, saved_state_;
  // Per node, 3 x nodes: velocity, pseudo- and true acceleration (spatial), angular velocity,
  // pseudo- and true angular acceleration (material).
  struct Motion {
    Eigen::Matrix3Xd v, a, vdot, w, alpha, wdot;

    std::array<Eigen::Matrix3Xd*, 6> All() { return {&v, &a, &vdot, &w, &alpha, &wdot}; }

    void Resize(int nodes) {
      for (Eigen::Matrix3Xd* m : All()) m->setZero(3, nodes);
    }
    // Copies without allocating (the sizes match); Swap() exchanges buffers, not contents.
    void CopyFrom(Motion& o) {
      const auto from = o.All(), to = All();
      for (std::size_t i = 0; i < to.size(); ++i) *to[i] = *from[i];
    }
    void Swap(Motion& o) {
      const auto other = o.All(), mine = All();
      for (std::size_t i = 0; i < mine.size(); ++i) mine[i]->swap(*other[i]);
    }
  };
  // At t_n, at t_(n+1) while a step iterates, and at the start of the step (to restore).
  Motion motion_, motion_new_, motion_save_;
  RodLoads start_loads_, target_loads_, loads_;
  BlockTridiagonalSystem system_;
  Eigen::VectorXd residual_, increment_;
  Eigen::Matrix3Xd correction_;  // workspace of CosseratRod::Retract
  Eigen::Matrix3Xd theta_;       // material rotation increments Theta of the step, per node
  CosseratRod::ElementKinematics kinematics_;
};

}  // namespace cosmems
