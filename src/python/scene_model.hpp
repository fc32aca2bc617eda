#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "cosmems/analysis/modal_analysis.hpp"
#include "cosmems/core/units.hpp"
#include "cosmems/linalg/symmetric_band_matrix.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems::python {

/// The linear model of a scene's structure, whatever it is (a planar or spatial beam, a device),
/// on its netlist's FrameModel: the Python module's Model. The core's matrices are in the model's
/// internal units; the conversions to SI at this interface are here, once.
///
/// A free degree of freedom is a translation (m) or a rotation (rad); with S the diagonal of
/// dof_scale() (the unit length for a translation, 1 for a rotation), displacement in SI is
/// S d, a load in SI is (F L) S^-1 f, and the matrices are K_SI = F L S^-1 K S^-1 and
/// M_j,SI = F L T^(2j+2) S^-1 M_j S^-1 for the unit force F, length L and time T.
class SceneModel {
 public:
  /// One free degree of freedom: "A.uy" for a device's named node or body, "node7.uy" for a
  /// beam's node (counted from its clamped end) or a device's unnamed one.
  struct Dof {
    std::string label;
    bool translation = true;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  ///< m: its node, or its body's centre
  };

  /// The model of `scene`'s structure, its axial preload included. Throws std::invalid_argument
  /// for a structure the core refuses.
  explicit SceneModel(const Scene& scene);

  const SymmetricBandMatrix& Stiffness() const { return model_.Stiffness(); }
  /// M_2j, j = 0 ... SeriesOrder(), of D(w) = K - sum_j w^(2j+2) M_2j.
  const SymmetricBandMatrix& Mass(int j) const { return model_.Mass(j); }
  int SeriesOrder() const { return model_.SeriesOrder(); }
  const UnitSystem& units() const { return model_.units(); }
  /// The `count` lowest modes of the power-series pencil (internal units, x^T M_0 x = 1).
  ModalResult Modal(int count) const;

  int size() const { return static_cast<int>(dofs_.size()); }
  const std::vector<Dof>& dofs() const { return dofs_; }
  /// m per internal unit of each displacement: the unit length for translations, 1 for rotations.
  const Eigen::VectorXd& dof_scale() const { return scale_; }

  /// K (j < 0) or M_2j in SI, the whole symmetric matrix.
  Eigen::SparseMatrix<double> MatrixSi(int j) const;
  /// The scene's [loads] as one load vector (N, N m): its point forces, moments and distributed
  /// loads, at the amplitude 1 that a transient's time function scales.
  const Eigen::VectorXd& loads_si() const { return loads_si_; }

 private:
  FrameModel model_;
  std::vector<Dof> dofs_;
  Eigen::VectorXd scale_;
  Eigen::VectorXd loads_si_;
};

}  // namespace cosmems::python
