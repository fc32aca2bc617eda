#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "cosmems/analysis/comb_drive.hpp"
#include "cosmems/analysis/frame_static_analysis.hpp"
#include "cosmems/analysis/frame_transient_analysis.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// One comb drive at its static equilibrium.
struct CombDriveState {
  double force_n = 0.0;        ///< the engagement force along its direction
  double engagement_m = 0.0;   ///< its body's centre moved along its direction
  double capacitance_f = 0.0;  ///< at that engagement
  /// the comb's voltage at the side instability: every comb's voltage scaled by one factor
  /// until the suspension no longer holds the bodies across their fingers (infinity when no
  /// factor up to 1e6 reaches it)
  double side_instability_voltage_v = std::numeric_limits<double>::infinity();
};

/// A device's statics with its comb drives: the frame's linear statics under the scene's loads
/// and every comb's engagement force, and each comb's state.
struct CombDriveSolution {
  FrameStaticSolution statics;
  std::vector<CombDriveState> combs;
  /// the factor of every comb's voltage at the side instability (infinity: none up to 1e6)
  double side_instability_factor = std::numeric_limits<double>::infinity();
};

namespace internal {

// The displacement [m] of body `at` along `along` under a 1 N force along `pushed` at body
// `load` (K^-1 by the factor `solver`).
inline double BodyCompliance(const FrameModel& model, const SpdSolver& solver, int load,
                             const Eigen::Vector3d& pushed, int at, const Eigen::Vector3d& along) {
  FrameLoadCase unit;
  unit.points.push_back({-1, load, pushed, Eigen::Vector3d::Zero()});
  Eigen::VectorXd u = AssembleFrameLoads(model, unit);
  solver.SolveInPlace(u);
  const int carrier = model.mesh().body_carrier[at];
  return model.CarrierMotion(u, carrier).head<3>().dot(along) * model.units().length;
}

}  // namespace internal

/// Linear statics of a device driven by comb drives (CombDrive: each force at its body's
/// centre), and the side instability of the combs together: with every comb's voltage scaled by
/// s, each comb's engagement x_c(s) (the scene's loads held, the combs' forces growing as s^2)
/// and its negative stiffness k_c(s) across its fingers, the suspension gives way sideways at
/// the lowest s where K - sum_c k_c l_c l_c^T turns singular: where the largest eigenvalue of
/// D C D, C the bodies' compliance across the combs (C_ij: body i's motion along l_i under 1 N
/// along l_j at body j) and D = diag(sqrt(k_c)), reaches 1. For one comb this is
/// k_c(s) = 1 / C, the suspension's stiffness across the fingers (Legtenberg et al. 1996).
/// When every comb is at 0 V, the factor scales 1 V on each. Statuses as SolveFrameStatic's.
inline CombDriveSolution SolveCombDrives(const FrameModel& model, const FrameLoadCase& loads,
                                         const std::vector<CombDrive>& combs) {
  const int bodies = static_cast<int>(model.description().bodies.size());
  for (const CombDrive& comb : combs) {
    comb.Validate();
    if (comb.body >= bodies) throw std::invalid_argument("comb drive: names no body");
  }
  bool any_voltage = false;
  for (const CombDrive& comb : combs) any_voltage = any_voltage || comb.voltage != 0.0;
  const auto reference = [&](const CombDrive& comb) { return any_voltage ? comb.voltage : 1.0; };

  CombDriveSolution out;
  FrameLoadCase driven = loads;
  for (const CombDrive& comb : combs) {
    driven.points.push_back(
        {-1, comb.body, comb.Force(comb.voltage) * comb.Axis(), Eigen::Vector3d::Zero()});
  }
  out.statics = SolveFrameStatic(model, driven);
  if (out.statics.status != Status::kOk || combs.empty()) return out;

  const int m = static_cast<int>(combs.size());
  SpdSolver solver;
  if (solver.Compute(model.Stiffness(), SpdSolverKind::kAuto) != Status::kOk) return out;
  Eigen::MatrixXd lateral(m, m), engagement(m, m);
  Eigen::VectorXd held(m);  // the engagement of the scene's loads alone
  for (int i = 0; i < m; ++i) {
    const CombDrive& c = combs[i];
    CombDriveState& state = out.combs.emplace_back();
    state.force_n = c.Force(c.voltage);
    state.engagement_m = out.statics.bodies[c.body].head<3>().dot(c.Axis());
    state.capacitance_f = c.Capacitance(state.engagement_m);
    held[i] = state.engagement_m;
    for (int j = 0; j < m; ++j) {
      const CombDrive& d = combs[j];
      lateral(i, j) =
          internal::BodyCompliance(model, solver, d.body, d.Lateral(), c.body, c.Lateral());
      engagement(i, j) =
          internal::BodyCompliance(model, solver, d.body, d.Axis(), c.body, c.Axis());
      held[i] -= engagement(i, j) * d.Force(d.voltage);
    }
  }
  // The largest eigenvalue of D C D at the factor s, less one.
  const auto excess = [&](double s) {
    Eigen::VectorXd root(m);
    for (int i = 0; i < m; ++i) {
      double x = held[i];
      for (int j = 0; j < m; ++j) x += engagement(i, j) * combs[j].Force(s * reference(combs[j]));
      root[i] = std::sqrt(combs[i].SideStiffness(s * reference(combs[i]), x));
    }
    const Eigen::MatrixXd scaled = root.asDiagonal() * lateral * root.asDiagonal();
    return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(scaled, Eigen::EigenvaluesOnly)
               .eigenvalues()
               .maxCoeff() -
           1.0;
  };
  double lo = 0.0, hi = 1.0;
  while (excess(hi) < 0.0) {
    lo = hi;
    hi *= 2.0;
    if (hi > 1e6) return out;
  }
  while (hi - lo > 1e-15 * hi) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (excess(mid) < 0.0 ? lo : hi) = mid;
  }
  out.side_instability_factor = hi;
  for (int i = 0; i < m; ++i) {
    out.combs[i].side_instability_voltage_v = hi * std::abs(reference(combs[i]));
  }
  return out;
}

/// The comb drives of a frame's transient: each comb's engagement force at 1 V at its body's
/// centre, a pattern the run scales by the square of the comb's voltage in time (the force does
/// not depend on the engagement, so the drive is a load).
inline FrameDrives CombDriveLoads(const FrameModel& model, const std::vector<CombDrive>& combs) {
  FrameDrives out;
  out.patterns.resize(model.FreeDofCount(), static_cast<Eigen::Index>(combs.size()));
  for (std::size_t c = 0; c < combs.size(); ++c) {
    combs[c].Validate();
    FrameLoadCase unit;
    unit.points.push_back(
        {-1, combs[c].body, combs[c].Force(1.0) * combs[c].Axis(), Eigen::Vector3d::Zero()});
    out.patterns.col(static_cast<Eigen::Index>(c)) = AssembleFrameLoads(model, unit);
    out.voltages.push_back(combs[c].Drive());
  }
  return out;
}

}  // namespace cosmems
