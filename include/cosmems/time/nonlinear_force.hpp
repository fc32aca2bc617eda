#pragma once

#include <Eigen/Core>

#include "cosmems/linalg/symmetric_band_matrix.hpp"

namespace cosmems {

/// A displacement-dependent internal force r(d) with its consistent tangent dr/dd, added to a
/// linear structure: M a + C v + K d + r(d) = f. Geometric stiffening, stretching, contact and
/// surface forces implement it. Evaluate() runs inside Newton iterations: it must allocate
/// nothing, and it reports a state outside its domain by returning false (the step is then cut).
class NonlinearForce {
 public:
  virtual ~NonlinearForce() = default;

  /// Adds r(d) to `force` and dr/dd to `tangent` (the structure's band pattern), both in the
  /// model's internal units.
  virtual bool Evaluate(const Eigen::VectorXd& d, Eigen::VectorXd& force,
                        SymmetricBandMatrix& tangent) = 0;
};

}  // namespace cosmems
