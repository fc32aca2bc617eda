#include "cosmems/analysis/frame_transient_analysis.hpp"

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "cosmems/analysis/beam_stepper_factory.hpp"
#include "cosmems/analysis/frame_modal_analysis.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/transient_recorder.hpp"

namespace cosmems {

OutputPoint FrameMotionComponent(const FrameModel& model, const FrameRecordPoint& point, int c) {
  OutputPoint out;
  out.length_unit = model.units().length;
  const StructureDescription& s = model.description();
  const int nodes = static_cast<int>(s.nodes.size());
  const int bodies = static_cast<int>(s.bodies.size());
  const int members = static_cast<int>(s.members.size());
  if (point.node < 0 && point.body < 0) {
    if (point.member < 0 || point.member >= members || !(point.at >= 0.0 && point.at <= 1.0)) {
      throw std::invalid_argument("a recorded point names no point of a member of the structure");
    }
    // The member's interpolation is linear in the state: its weights are its values on the
    // unit states of the element's degrees of freedom.
    const int e = model.Locate(point.member, point.at).first;
    Eigen::VectorXd unit = Eigen::VectorXd::Zero(model.FreeDofCount());
    for (int r : model.ElementDofs(e)) {
      if (r < 0) continue;
      unit[r] = 1.0;
      const double w = model.MemberMotion(unit, point.member, point.at)[c];
      unit[r] = 0.0;
      if (w != 0.0) out.weights.emplace_back(r, w);
    }
    return out;
  }
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

FrameTransientResult RunFrameTransient(const FrameModel& model, const FrameLoadCase& loads,
                                       const TransientOptions& options,
                                       const std::vector<FrameRecordPoint>& record,
                                       NonlinearForce* force, const FrameDrives& drives,
                                       int watched_component) {
  options.Validate();
  if (record.empty()) throw std::invalid_argument("a frame transient records at least one point");
  // The longest member: the recorder declares a run diverged beyond a thousand of it.
  TransientRecorder recorder(options, model.units().length);
  FrameTransientResult out;
  TransientResult& result = out.run;
  const int n = model.FreeDofCount();
  const Eigen::VectorXd pattern = AssembleFrameLoads(model, loads);
  const auto driven = static_cast<Eigen::Index>(drives.voltages.size());
  if (drives.patterns.cols() != driven || (driven > 0 && drives.patterns.rows() != n)) {
    throw std::invalid_argument("frame drives: one voltage per pattern of the model's size");
  }
  Eigen::MatrixXd patterns(n, 1 + driven);
  patterns.col(0) = pattern;
  Eigen::VectorXd mean = pattern;  // the loads and the drives' mean forces
  for (Eigen::Index c = 0; c < driven; ++c) {
    const VoltageDrive& v = drives.voltages[static_cast<std::size_t>(c)];
    patterns.col(1 + c) = drives.patterns.col(c);
    mean += (v.dc * v.dc + 0.5 * v.ac * v.ac) * drives.patterns.col(c);
  }
  Eigen::VectorXd statics, moved;
  result.status = SolveFrameDisplacement(model, pattern, statics);
  if (result.status != Status::kOk) return out;
  if (driven > 0) {
    result.status = SolveFrameDisplacement(model, mean, moved);
    if (result.status != Status::kOk) return out;
  }
  const Eigen::VectorXd& watched = driven > 0 ? moved : statics;

  std::vector<OutputPoint> channels;
  for (const FrameRecordPoint& point : record) {
    for (int c = 0; c < 3; ++c) channels.push_back(FrameMotionComponent(model, point, c));
  }
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double u = std::abs(channels[c].Evaluate(watched));
    if (u > largest) {
      largest = u;
      out.watched_component = c;
    }
  }
  if (watched_component >= 0) out.watched_component = watched_component;

  const BeamStepperSetup setup = MakeBeamStepper(model, options.Stepper(), patterns, force);
  result.status = setup.status;
  if (setup.status != Status::kOk) return out;
  BeamStepper& stepper = *setup.stepper;
  stepper.Watch(channels[out.watched_component]);
  // The amplitudes at the end of step i: the loads' time function, each drive's V(t)^2; the
  // electrodes' pressure scaled alike.
  Eigen::VectorXd s(1 + driven);
  const auto amplitudes = [&](long i) {
    const double t = static_cast<double>(i) * options.time_step;
    s[0] = options.Amplitude(i);
    for (Eigen::Index c = 0; c < driven; ++c) {
      s[1 + c] = drives.voltages[static_cast<std::size_t>(c)].SquaredAt(t);
    }
    if (drives.electrodes != nullptr) {
      drives.electrodes->SetScale(drives.electrode_voltage.SquaredAt(t));
    }
  };
  amplitudes(0);
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
        amplitudes(i);
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
