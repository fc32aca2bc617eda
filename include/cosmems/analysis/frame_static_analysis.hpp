#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosmems/analysis/frame_load_case.hpp"
#include "cosmems/analysis/nonlinear_static_analysis.hpp"
#include "cosmems/beam/element_loads.hpp"
#include "cosmems/beam/force_sum.hpp"
#include "cosmems/core/status.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/linalg/spd_solver.hpp"
#include "cosmems/structure/frame_element_force.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// What an anchor exerts on the structure at its node (global axes, SI; the moment about the
/// node). With the loads it balances the structure.
struct FrameReaction {
  int node = 0;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
};

/// A frame's static solution in SI (global axes) and the reduced displacements it came from.
struct FrameStaticSolution {
  Status status = Status::kOk;
  Eigen::VectorXd displacement;            ///< reduced, internal units
  std::vector<FrameModel::Motion> nodes;   ///< (u [m], theta [rad]) of every description node
  std::vector<FrameModel::Motion> bodies;  ///< of every body's centre
  std::vector<FrameReaction> reactions;    ///< at every anchored node
  double max_deflection = 0.0;  ///< m: the largest displacement toward the substrate (-u_y)
  /// The largest von Mises stress at a member's end: the normal stress |N|/A + |M_z| c_y / I_z +
  /// |M_y| c_z / I_y with the torsional shear T c / J (c the section's short side).
  double max_stress_pa = 0.0;
  double axial_force_n = 0.0;  ///< the member axial force of largest magnitude, tension > 0
};

/// The reduced load vector (internal units) of a frame load case: point loads through the
/// motion of their node or body, the distributed load by each element's consistent loads.
/// Throws std::invalid_argument for a non-finite value or an entry outside the structure.
Eigen::VectorXd AssembleFrameLoads(const FrameModel& model, const FrameLoadCase& loads);

namespace internal {

// Each element's end forces in its own axes, K u + r(u) - f (internal units; r the shares of
// the nonlinear forces given: stretching, a gap pressure; f the element's share of the loads: the
// distributed load and the point loads between its ends): the reactions, the axial forces and
// the stresses all come from them.
FrameModel::ElementVector ElementEndForces(const FrameModel& model, const Eigen::VectorXd& d, int e,
                                           const FrameLoadCase& loads,
                                           const std::vector<FrameElementForce*>& forces = {});

}  // namespace internal

/// The reduced displacement d (internal units) of K d = f, the linear statics alone. A structure
/// left free to move (a mechanism) has a singular K: Status::kNotPositiveDefinite and d zero,
/// never a NaN. `solver_kind`: the factorisation (SpdSolver::Choose by default).
Status SolveFrameDisplacement(const FrameModel& model, const Eigen::VectorXd& f, Eigen::VectorXd& d,
                              SpdSolverKind solver_kind = SpdSolverKind::kAuto);

namespace internal {

// The motions (SI) of every node and body of the displacement out.displacement.
void RecoverFrameMotions(const FrameModel& model, FrameStaticSolution& out);

// The motions of every node and body, the largest deflection toward the substrate, the members'
// largest stress and axial force and the reactions of the solved displacement out.displacement
// (with the nonlinear forces' shares of the end forces).
void RecoverFrameStatic(const FrameModel& model, const FrameLoadCase& loads,
                        const std::vector<FrameElementForce*>& forces, FrameStaticSolution& out);

}  // namespace internal

/// Linear statics of a frame, K u = f, with the nodes' and bodies' motions, the reactions at
/// the anchors and the members' largest stress and axial force (SolveFrameDisplacement's
/// statuses).
FrameStaticSolution SolveFrameStatic(const FrameModel& model, const FrameLoadCase& loads,
                                     SpdSolverKind solver_kind = SpdSolverKind::kAuto);

/// Statics of a frame under nonlinear forces, K u + r(u) + lambda r_s(u) = lambda f (Nonlinear-
/// StaticSolve: adaptive load steps, Newton with the consistent tangent), r the sum of `forces`
/// (members that stretch as they bend) and r_s the sum of the `ramped` forces, which grow with
/// the loads (the pressures across the gap: an electrode's V^2 rises from 0 with them, and the
/// Casimir and van der Waals pressures leave no unloaded equilibrium to start from). The results
/// are SolveFrameStatic's; the end forces, reactions and axial forces carry each force's share. A
/// state the solve cannot reach is Status::kNotConverged, with no results but the status (a
/// device pulled past its pull-in voltage has none).
FrameStaticSolution SolveFrameNonlinearStatic(const FrameModel& model,
                                              const std::vector<FrameElementForce*>& forces,
                                              const FrameLoadCase& loads,
                                              const std::vector<FrameElementForce*>& ramped = {},
                                              const NonlinearStaticOptions& options = {});

}  // namespace cosmems
