#include "cosmems/analysis/frame_pullin_analysis.hpp"

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace cosmems {

int PullInControlCarrier(const FrameModel& model, FrameGapForce<ElectrostaticPressure>& unit) {
  const int n = model.FreeDofCount();
  Eigen::VectorXd r = Eigen::VectorXd::Zero(n), d;
  ForceTangent tangent(n, model.Stiffness().bandwidth());
  if (!unit.Evaluate(Eigen::VectorXd::Zero(n), r, tangent)) return -1;
  if (SolveFrameDisplacement(model, r, d) != Status::kOk) return -1;
  int best = -1;
  double largest = 0.0;
  for (int c = 0; c < static_cast<int>(model.mesh().carriers.size()); ++c) {
    const int dof = model.CarrierDof(c, 1);
    if (dof >= 0 && std::abs(d[dof]) > largest) {
      largest = std::abs(d[dof]);
      best = c;
    }
  }
  return best;
}

FramePullInResult SolveFramePullIn(const FrameModel& model, const FramePullInOptions& options,
                                   const std::vector<FrameElementForce*>& others) {
  FramePullInResult out;
  FrameGapForce<ElectrostaticPressure> unit = MakeFrameElectrostaticForce(model, options, 1.0);
  out.capacitance_f = unit.Capacitance(Eigen::VectorXd::Zero(model.FreeDofCount()));
  out.control_carrier = PullInControlCarrier(model, unit);
  if (out.control_carrier < 0) {
    out.fold.status = Status::kNotPositiveDefinite;
    return out;
  }
  OutputPoint control;
  control.weights = {{model.CarrierDof(out.control_carrier, 1), 1.0}};
  control.length_unit = model.units().length;
  ForceSum sum;
  for (FrameElementForce* force : others) sum.Add(*force);
  const double gap = options.electrodes.gap;
  FoldPath<FrameModel, FrameGapForce<ElectrostaticPressure>> path(
      model, unit, control, gap, options.newton, others.empty() ? nullptr : &sum);
  out.fold = TraceFold(path, options.fold, gap);
  if (out.fold.status != Status::kOk) return out;
  out.shape.displacement = out.fold.displacement;
  unit.SetScale(path.accepted_load());  // V^2: the pressure that holds the last stable state
  std::vector<FrameElementForce*> forces = others;
  forces.push_back(&unit);
  internal::RecoverFrameStatic(model, FrameLoadCase{}, forces, out.shape);
  out.fold.displacement_m = out.shape.max_deflection;
  return out;
}

}  // namespace cosmems
