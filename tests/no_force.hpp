#pragma once

// r(d) = 0: a nonlinear force that adds nothing, for the integrators' linear limits and for
// surface pressures ramped alone.

#include "cosmems/beam/nonlinear_force.hpp"

namespace cosmems::test {

class NoForce final : public NonlinearForce {
 public:
  bool Evaluate(const Eigen::VectorXd&, Eigen::VectorXd&, ForceTangent&) override { return true; }
};

}  // namespace cosmems::test
