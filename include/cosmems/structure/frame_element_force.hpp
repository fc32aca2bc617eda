#pragma once

#include <Eigen/Core>

#include "cosmems/beam/nonlinear_force.hpp"
#include "cosmems/structure/frame_model.hpp"

namespace cosmems {

/// A nonlinear force on a frame that acts element by element, so the recovery of the members'
/// end forces (reactions, stresses, axial forces) can take each element's share of it: the
/// members' stretching, a pressure across the gap.
class FrameElementForce : public NonlinearForce {
 public:
  /// The force's share on element e, in the element's own axes (internal units): what the
  /// linear element's K u leaves out of its end forces. A share carried by a body, not by a
  /// member, is in no element.
  virtual FrameModel::ElementVector LocalForce(const Eigen::VectorXd& d, int e) const = 0;
};

}  // namespace cosmems
