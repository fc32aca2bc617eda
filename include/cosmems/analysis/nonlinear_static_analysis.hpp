#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "cosmems/analysis/static_analysis.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_case.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/core/nonlinear_force.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/linalg/band_rank_one_cholesky.hpp"
#include "cosmems/time/newton_options.hpp"

namespace cosmems {

struct NonlinearStaticOptions {
  NewtonOptions newton;
  /// A load step that fails is halved; below this fraction of the full load the solve gives up
  /// (Status::kNotConverged), keeping the last converged state.
  double min_load_step = 1.0 / 1024.0;
  /// Backtracking halvings of a Newton correction before it is taken whole anyway.
  int max_line_search = 8;
  /// Where the first load step's Newton starts (reduced, internal units); empty: the unloaded
  /// beam. A beam pressed onto the substrate starts there, say.
  Eigen::VectorXd start;
};

struct NonlinearStaticSolution {
  Status status = Status::kOk;
  Eigen::VectorXd displacement;  ///< reduced, internal units; the last converged state on failure
  double load_factor = 0.0;      ///< the share of the load carried: 1 when solved
  int iterations = 0;            ///< Newton iterations over all load steps
  int load_steps = 0;            ///< accepted load steps
};

/// Statics with a nonlinear internal force: K d + r(d) + lambda r_s(d) = lambda f, lambda from
/// 0 to 1, r_s an optional stateless force ramped with the loads (surface pressures, which leave no
/// unloaded equilibrium to start from; a fold of the ramp stops the load steps there).
///
/// Adaptive load stepping: a step that Newton solves doubles the next one (up to what remains),
/// one that fails is retried at half the size from the last converged state. Newton uses the
/// force's consistent tangent (band plus rank-one) and a backtracking line search on the
/// residual norm, so a correction that overshoots a stiffening force is shortened instead of
/// thrown away. Converged on NewtonOptions' relative residual or increment.
template <int Dim>
NonlinearStaticSolution SolveNonlinearStatic(const BeamModel<Dim>& model, NonlinearForce& force,
                                             const LoadCase& loads,
                                             const NonlinearStaticOptions& options = {},
                                             NonlinearForce* ramped = nullptr) {
  const int n = model.FreeDofCount();
  const SymmetricBandMatrix& k = model.Stiffness();
  const Eigen::VectorXd f = AssembleLoads(model, loads);
  NonlinearStaticSolution out;
  out.displacement = Eigen::VectorXd::Zero(n);
  if (options.start.size() == n) out.displacement = options.start;
  ForceTangent tangent(n, k.bandwidth());
  ForceTangent ramped_tangent(n, k.bandwidth());
  Eigen::VectorXd rs = Eigen::VectorXd::Zero(n);
  SymmetricBandMatrix jacobian(n, k.bandwidth());
  BandRankOneCholesky factor;
  Eigen::VectorXd d(n), r(n), residual(n), step(n), trial(n), kd(n);

  // R(d) = K d + r(d) - lambda f, and the size of the terms it balances.
  auto evaluate = [&](const Eigen::VectorXd& x, double lambda, double& reference) {
    r.setZero();
    tangent.Clear();
    if (!force.Evaluate(x, r, tangent)) return false;
    if (ramped) {
      rs.setZero();
      ramped_tangent.Clear();
      if (!ramped->Evaluate(x, rs, ramped_tangent)) return false;
      r += lambda * rs;
      tangent.band().mutable_data() += lambda * ramped_tangent.band().data();
    }
    k.Multiply(x, kd);
    residual = kd + r - lambda * f;
    reference = kd.norm() + r.norm() + lambda * f.norm();
    return residual.allFinite();
  };

  auto newton = [&](double lambda) {
    double reference = 0.0;
    if (!evaluate(d, lambda, reference)) return Status::kNonFinite;
    int settles = 0;
    double previous = std::numeric_limits<double>::infinity();
    for (int iteration = 1; iteration <= options.newton.max_iterations; ++iteration) {
      ++out.iterations;
      // kd serves as the bound's work vector: the next evaluation forms K d again.
      const double norm = residual.norm();
      bool converged = norm <= options.newton.residual_tolerance * reference ||
                       NewtonOptions::StalledAtRoundOff(norm, previous,
                                                        [&] { return k.ProductRoundOff(d, kd); });
      previous = norm;
      if (!converged) {
        jacobian.mutable_data() = k.data() + tangent.band().data();
        const Status factored =
            factor.Compute(jacobian, tangent.rank_one_scale(), tangent.rank_one_vector());
        if (factored != Status::kOk) return factored;
        step = -residual;
        factor.SolveInPlace(step);
        double alpha = 1.0;
        for (int cut = 0;; ++cut) {
          trial = d + alpha * step;
          if ((evaluate(trial, lambda, reference) &&
               residual.norm() < (1.0 - 1e-4 * alpha) * norm) ||
              cut == options.max_line_search) {
            break;
          }
          alpha *= 0.5;
        }
        d = trial;
        if (!residual.allFinite()) return Status::kNonFinite;
        converged = alpha * step.norm() <= options.newton.increment_tolerance * d.norm();
      }
      if (!converged) continue;
      // Converged for the force's present state; a force that changes it there starts Newton
      // afresh.
      if (force.Settle(d)) return Status::kOk;
      if (++settles > options.newton.max_settles) return Status::kNotConverged;
      iteration = 0;
      previous = std::numeric_limits<double>::infinity();
      if (!evaluate(d, lambda, reference)) return Status::kNonFinite;
    }
    return Status::kNotConverged;
  };

  double lambda = 0.0;
  double increment = 1.0;
  out.status = Status::kOk;
  while (lambda < 1.0) {
    const double target = std::min(1.0, lambda + increment);
    d = out.displacement;
    const Status status = newton(target);
    if (status == Status::kOk) {
      force.Commit(d);
      out.displacement = d;
      lambda = target;
      ++out.load_steps;
      increment = std::min(2.0 * increment, 1.0 - lambda);
    } else {
      force.Revert();
      increment *= 0.5;
      if (increment < options.min_load_step) {
        out.status = status;
        break;
      }
    }
  }
  out.load_factor = lambda;
  return out;
}

}  // namespace cosmems
