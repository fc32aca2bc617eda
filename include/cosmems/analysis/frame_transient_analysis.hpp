#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/analysis/frame_modal_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/transient_options.hpp"
#include "cosmems/analysis/transient_recorder.hpp"
#include "cosmems/analysis/transient_result.hpp"
#include "cosmems/beam/output_point.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// A point whose motion a frame's transient records: a description node, or a body's centre.
struct FrameRecordPoint {
  int node = -1;  ///< a description node, or -1
  int body = -1;  ///< a body, when node is -1
};

/// A frame's transient run: its status, steps and timing in `run`, whose output (extremes and
/// divergence check, every step) is the watched component, and the motion of every recorded
/// point at the samples the history keeps.
struct FrameTransientResult {
  TransientResult run;
  /// 0, 1, 2: ux, uy or uz of the first recorded point, the one its static response to the
  /// loads is largest in (uy when the loads do not move it)
  int watched_component = 1;
  /// one row per sample of run.time_s; ux, uy, uz [m] of each recorded point in turn
  Eigen::MatrixXd history;
};

/// The displacement component c (0, 1, 2: global x, y, z) of a recorded point as a linear
/// functional of the reduced displacement: a body's centre reads its own degree of freedom, a
/// node on a body or free reads its carrier's motion through the node's transform.
inline OutputPoint FrameMotionComponent(const FrameModel& model, const FrameRecordPoint& point,
                                        int c) {
  OutputPoint out;
  out.length_unit = model.units().length;
  const int nodes = static_cast<int>(model.description().nodes.size());
  const int bodies = static_cast<int>(model.description().bodies.size());
  const bool body = point.node < 0;
  if (body ? point.body < 0 || point.body >= bodies : point.node >= nodes) {
    throw std::invalid_argument("a recorded point names no node or body of the structure");
  }
  const int carrier =
      body ? model.mesh().body_carrier[point.body] : model.mesh().nodes[point.node].carrier;
  const Eigen::Matrix<double, 6, 6> t =
      body ? Eigen::Matrix<double, 6, 6>::Identity() : model.NodeTransform(point.node);
  for (int k = 0; k < 6; ++k) {
    const int r = model.CarrierDof(carrier, k);
    if (r >= 0 && t(c, k) != 0.0) out.weights.emplace_back(r, t(c, k));
  }
  return out;
}

/// A transient run of a frame under `loads` (one spatial pattern times the time function) by
/// the BeamStepper of `options.path` (MakeBeamStepper: the Newmark family on the full band
/// model, or modal propagation with the static correction of the truncated modes), recording
/// the displacement of each point of `record` (at least one). `options.output_x` is not used:
/// the watched output is a component of the first recorded point. A static start deflects the
/// frame under the loads (removed at t = 0); a mechanism is Status::kNotPositiveDefinite. With
/// a nonlinear `force` (the members' stretching; it must outlive the run) the Newmark family
/// takes its Newton path, the modal path holds the force over each step, and a static start
/// solves the nonlinear statics.
inline FrameTransientResult RunFrameTransient(const FrameModel& model, const FrameLoadCase& loads,
                                              const TransientOptions& options,
                                              const std::vector<FrameRecordPoint>& record,
                                              NonlinearForce* force = nullptr) {
  options.Validate();
  if (record.empty()) throw std::invalid_argument("a frame transient records at least one point");
  // The longest member: the recorder declares a run diverged beyond a thousand of it.
  TransientRecorder recorder(options, model.units().length);
  FrameTransientResult out;
  TransientResult& result = out.run;
  const int n = model.FreeDofCount();
  const Eigen::VectorXd pattern = AssembleFrameLoads(model, loads);
  Eigen::VectorXd statics;
  result.status = SolveFrameDisplacement(model, pattern, statics);
  if (result.status != Status::kOk) return out;

  std::vector<OutputPoint> channels;
  for (const FrameRecordPoint& point : record) {
    for (int c = 0; c < 3; ++c) channels.push_back(FrameMotionComponent(model, point, c));
  }
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double u = std::abs(channels[c].Evaluate(statics));
    if (u > largest) {
      largest = u;
      out.watched_component = c;
    }
  }

  const BeamStepperSetup setup = MakeBeamStepper(model, options.Stepper(), pattern, force);
  result.status = setup.status;
  if (setup.status != Status::kOk) return out;
  BeamStepper& stepper = *setup.stepper;
  stepper.Watch(channels[out.watched_component]);
  Eigen::VectorXd s = Eigen::VectorXd::Constant(1, options.Amplitude(0));
  Eigen::VectorXd d0 = Eigen::VectorXd::Zero(n);
  if (options.start_static && force != nullptr) {
    NonlinearStaticSolve solve(model.Stiffness(), *force, {}, nullptr);
    const NonlinearStaticSolution deflected = solve.Solve(pattern);
    result.status = deflected.status;
    if (result.status != Status::kOk) return out;
    d0 = deflected.displacement;
  } else if (options.start_static) {
    d0 = statics;
  }
  result.status = stepper.Initialize(d0, Eigen::VectorXd::Zero(n), s);
  if (result.status != Status::kOk) return out;

  std::vector<double> rows;
  const long kept = std::min<long>(recorder.steps() + 1, options.max_history + 2);
  rows.reserve(static_cast<std::size_t>(kept) * channels.size());
  recorder.Run(
      result,
      [&](long i) {
        s[0] = options.Amplitude(i);
        return stepper.Step(s);
      },
      [&] { return stepper.Watched(); },
      [&] {
        const Eigen::VectorXd& d = stepper.displacement();
        for (const OutputPoint& channel : channels) rows.push_back(channel.Evaluate(d));
      });
  recorder.Finish(result);
  const Eigen::Index columns = static_cast<Eigen::Index>(channels.size());
  out.history =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          rows.data(), static_cast<Eigen::Index>(rows.size()) / columns, columns);
  return out;
}

}  // namespace cosmems
