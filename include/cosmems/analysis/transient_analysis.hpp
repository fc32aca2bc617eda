#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/analysis/output_point.hpp"
#include "cosmems/analysis/step_timing.hpp"
#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/load_vector.hpp"
#include "cosmems/linalg/band_cholesky.hpp"
#include "cosmems/time/damping_model.hpp"
#include "cosmems/time/generalized_alpha_parameters.hpp"
#include "cosmems/time/linear_newmark_integrator.hpp"
#include "cosmems/time/load_time_function.hpp"
#include "cosmems/time/modal_model.hpp"
#include "cosmems/time/modal_propagator.hpp"
#include "cosmems/time/nonlinear_newmark_integrator.hpp"

namespace cosmems {

/// How a transient run advances in time.
enum class TimePath {
  kNewmarkFamily,  ///< full order, the linear fast path with GeneralizedAlphaParameters
  kModal,          ///< `modes` modes propagated exactly, truncated modes statically
};

struct TransientOptions {
  double duration = 0.0;   ///< s
  double time_step = 0.0;  ///< s
  TimePath path = TimePath::kNewmarkFamily;
  GeneralizedAlphaParameters parameters;  ///< for kNewmarkFamily
  int modes = 0;                          ///< for kModal: >= 1
  /// false: from rest, loads applied by `time_function`; true: from the static deflection under
  /// the loads, which are removed at t = 0 (a release).
  bool start_static = false;
  LoadTimeFunction time_function;
  DampingModel damping;
  SpdSolverKind solver = SpdSolverKind::kAuto;
  double output_x = 0.0;    ///< m: where uy is recorded (the tip or mid-span)
  int max_history = 20000;  ///< samples kept in the history, evenly strided

  void Validate() const {
    RequirePositive("analysis.duration", duration);
    RequirePositive("analysis.time_step", time_step);
    if (time_step > duration) {
      throw std::invalid_argument("analysis.time_step = " + FormatValue(time_step) +
                                  ": longer than analysis.duration = " + FormatValue(duration));
    }
    if (path == TimePath::kModal && modes < 1) {
      throw std::invalid_argument("model.modes = " + std::to_string(modes) +
                                  ": the modal integrator needs at least one mode");
    }
  }
};

struct TransientResult {
  Status status = Status::kOk;
  long steps = 0;
  StepTiming step_time;
  double wall_time_s = 0.0;      ///< set-up and stepping
  double stepping_time_s = 0.0;  ///< the steps alone (their timed sum)
  double simulated_time_s = 0.0;
  double max_abs_output = 0.0;  ///< m: largest |uy| at the output point
  /// m: largest -uy at the output point, its deflection toward the substrate (0 when it never
  /// moves that way)
  double max_toward_substrate = 0.0;
  std::vector<double> time_s;  ///< history
  std::vector<double> output_m;

  double RealtimeFactor() const { return wall_time_s > 0.0 ? simulated_time_s / wall_time_s : 0.0; }
};

/// A transient run of `model` under `loads` (one spatial pattern times the time function), by
/// the full-order Newmark family or by exact modal propagation. With a nonlinear `force`
/// (stretching, say) the Newmark family takes its Newton path and a static start solves the
/// nonlinear statics; the modal path is linear and refuses one (std::invalid_argument).
template <int Dim>
TransientResult RunTransient(const BeamModel<Dim>& model, const LoadCase& loads,
                             const TransientOptions& options, NonlinearForce* force = nullptr) {
  options.Validate();
  if (force && options.path == TimePath::kModal) {
    throw std::invalid_argument(
        "analysis.integrator = \"modal\": modal propagation is linear; a nonlinear theory "
        "needs a Newmark-family integrator");
  }
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  TransientResult result;
  const UnitSystem& units = model.units();
  const int n = model.FreeDofCount();
  const double dt = options.time_step / units.time;
  const auto steps = static_cast<long>(std::llround(options.duration / options.time_step));
  const Eigen::VectorXd pattern = AssembleLoads(model, loads);
  const OutputPoint output = OutputPoint::DeflectionAt(model, options.output_x);

  Eigen::VectorXd d0 = Eigen::VectorXd::Zero(n);
  if (options.start_static && force) {
    const NonlinearStaticSolution deflected = SolveNonlinearStatic(model, *force, loads);
    if (deflected.status != Status::kOk) {
      result.status = deflected.status;
      return result;
    }
    d0 = deflected.displacement;
  } else if (options.start_static) {
    const BandCholesky stiffness(model.Stiffness());
    if (stiffness.info() != Status::kOk) {
      result.status = stiffness.info();
      return result;
    }
    d0 = stiffness.Solve(pattern);
  }
  LoadTimeFunction time_function = options.time_function;
  if (options.start_static) time_function.kind = LoadTimeFunction::Kind::kZero;
  auto amplitude = [&](long i) {
    return time_function.Value(static_cast<double>(i) * options.time_step);
  };

  const long stride = std::max<long>(1, steps / std::max(1, options.max_history));
  std::vector<double> step_us;
  step_us.reserve(static_cast<std::size_t>(steps));
  auto record = [&](long i, double uy) {
    result.max_abs_output = std::max(result.max_abs_output, std::abs(uy));
    result.max_toward_substrate = std::max(result.max_toward_substrate, -uy);
    if (i % stride == 0 || i == steps) {
      result.time_s.push_back(static_cast<double>(i) * options.time_step);
      result.output_m.push_back(uy);
    }
  };
  // Runs the steps; `step(i)` advances to step i and returns its status, `sample()` reads uy.
  // A linear model whose output point has moved a thousand beam lengths has diverged (an
  // explicit step just above its stability limit grows geometrically long before it overflows).
  const double divergence = 1e3 * model.description().Length();
  auto run = [&](auto&& step, auto&& sample) {
    record(0, sample());
    for (long i = 1; i <= steps; ++i) {
      const auto before = Clock::now();
      const Status status = step(i);
      step_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - before).count());
      if (status != Status::kOk) {
        result.status = status;
        return;
      }
      result.steps = i;
      const double uy = sample();
      record(i, uy);
      if (std::abs(uy) > divergence) {
        result.status = Status::kDiverged;
        return;
      }
    }
  };

  if (options.path == TimePath::kModal) {
    ModalOptions modal_options;
    modal_options.count = options.modes;
    const ModalResult modes = SolveModal(model, modal_options);
    if (modes.status != Status::kOk) {
      result.status = modes.status;
      return result;
    }
    const ModalModel modal = MakeModalModel(model, modes, options.damping);
    const Eigen::MatrixXd residual = modal.ResidualFlexibility(model, pattern);
    ModalPropagator propagator(modal.coordinates, modal.shapes, pattern, residual, dt);
    Eigen::VectorXd s = Eigen::VectorXd::Constant(1, amplitude(0));
    propagator.Initialize(model.Mass(0) * d0, Eigen::VectorXd::Zero(n), s);
    const Eigen::RowVectorXd output_shapes = output.Evaluate(modal.shapes);
    const double output_static = output.Evaluate(residual.col(0).eval());
    run(
        [&](long i) {
          s[0] = amplitude(i);
          return propagator.Step(s);
        },
        [&] { return output_shapes.dot(propagator.modal_displacement()) + output_static * s[0]; });
  } else {
    RayleighDamping damping;
    if (options.damping.kind != DampingModel::Kind::kNone) {
      ModalOptions two;
      two.count = 2;
      const ModalResult lowest = SolveModal(model, two);
      const double w1 = 2.0 * kPi * lowest.modes.at(0).frequency_hz;
      const double w2 =
          lowest.modes.size() > 1 ? 2.0 * kPi * lowest.modes[1].frequency_hz : 3.0 * w1;
      damping = options.damping.ForFullModel(w1, w2, units);
    }
    // Returns false when the integrator could not start (the status says why).
    auto march = [&](auto& integrator) {
      Eigen::VectorXd f = pattern * amplitude(0);
      result.status = integrator.Initialize(d0, Eigen::VectorXd::Zero(n), f);
      if (result.status != Status::kOk) return false;
      run(
          [&](long i) {
            f = pattern * amplitude(i);
            return integrator.Step(f);
          },
          [&] { return output.Evaluate(integrator.displacement()); });
      return true;
    };
    bool started = false;
    if (force) {
      NonlinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), damping, *force,
                                            options.parameters, dt);
      started = march(integrator);
    } else {
      LinearNewmarkIntegrator integrator(model.Mass(0), model.Stiffness(), damping,
                                         options.parameters, dt, options.solver);
      started = march(integrator);
    }
    if (!started) return result;
  }
  for (const double us : step_us) result.stepping_time_s += 1e-6 * us;
  result.step_time = StepTiming::From(std::move(step_us));
  result.simulated_time_s = static_cast<double>(result.steps) * options.time_step;
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace cosmems
