#pragma once

#include <Eigen/Core>
#include <array>
#include <stdexcept>
#include <vector>

#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// The structure's six rigid motions about its mass centre (translations along x, y, z, then
/// rotations about axes through the centre) and its mass and rotary inertia in each: what a
/// mode's participation is measured against.
struct FrameRigidMotions {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();  ///< mass centre (internal units)
  Eigen::Matrix<double, 6, 1> total = Eigen::Matrix<double, 6, 1>::Zero();  ///< r^T M_0 r, all
                                                                            ///< dofs free
  Eigen::MatrixXd reduced;  ///< n x 6: each motion on the free degrees of freedom

  explicit FrameRigidMotions(const FrameModel& model);

  /// Rigid motion k (u, theta) at point p (internal units).
  FrameModel::Motion At(const Eigen::Vector3d& p, int k) const;
};

/// A frame's modes: each with its effective mass in the six rigid motions (ux, uy, uz, rx, ry,
/// rz about the mass centre) as a fraction of the whole structure's: (x^T M_0 r)^2 / r^T M_0 r
/// with x^T M_0 x = 1. Over all modes of a structure with nothing anchored they sum to one.
struct FrameModalResult {
  ModalResult modal;
  std::vector<std::array<double, 6>> participation;  ///< one per mode
};

/// Classifies a frame's mode by the field of its members (local axial, bending along the
/// thickness, bending across the width, torsion) that stores most of its strain energy: the
/// members' fields stay uncoupled in their own axes, and a body's motion is a mode of its
/// suspension.
ModeKind ClassifyFrameMode(const FrameModel& model, const Eigen::VectorXd& shape);

/// The lowest modes of a frame with the stiffness `stiffness` (K, or the tangent about a
/// deflected state; the model's pattern): the power-series polynomial eigenproblem across its
/// members (SolvePencilModes), and their kinds.
ModalResult SolveModal(const FrameModel& model, const SymmetricBandMatrix& stiffness,
                       const ModalOptions& options);

/// The lowest modes of the unloaded frame: the beam's SolveModal, for the code written for both.
ModalResult SolveModal(const FrameModel& model, const ModalOptions& options = {});

/// The participations of a frame's `modes` (FrameModalResult).
FrameModalResult WithParticipations(const FrameModel& model, ModalResult modes);

/// The lowest modes of the unloaded frame, with their participations.
FrameModalResult SolveFrameModal(const FrameModel& model, const ModalOptions& options = {});

/// The modes of a frame about its equilibrium `d` under the nonlinear `force` (K plus the
/// force's tangent there, which must fit the band: the members' stretching), with their
/// participations: a stretched device's stiffened modes. A tangent that is not positive
/// definite (past a fold) is Status::kNotPositiveDefinite.
FrameModalResult SolveFrameModalAbout(const FrameModel& model, NonlinearForce& force,
                                      const Eigen::VectorXd& d, const ModalOptions& options = {});

}  // namespace cosmems
