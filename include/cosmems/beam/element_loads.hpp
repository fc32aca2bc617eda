#pragma once

#include <Eigen/Core>
#include <cmath>

#include "cosmems/beam/element_interpolation.hpp"
#include "cosmems/beam/frame_element.hpp"

namespace cosmems {

/// An element's nodal load vector in the 3-D layout (two nodes of ux, uy, uz, rx, ry, rz).
using ElementLoads = Eigen::Matrix<double, 12, 1>;

/// The consistent nodal loads of a force F and a moment C acting at local coordinate xi of an
/// element of length l (the element's axes and internal units): each is weighted by the static
/// shape functions, so they do exactly the work of the load on any static element shape.
inline ElementLoads PointElementLoads(const FrameBases& bases, double l, double xi,
                                      const Eigen::Vector3d& force, const Eigen::Vector3d& moment) {
  const ShapeValues s = ShapeValues::At(bases, xi);
  ElementLoads f = ElementLoads::Zero();
  for (int node = 0; node < 2; ++node) {
    auto at = [&](NodalDof dof) -> double& { return f[6 * node + static_cast<int>(dof)]; };
    at(NodalDof::kUx) = force.x() * s.bar[node];
    at(NodalDof::kUy) =
        force.y() * s.bending[2 * node] + moment.z() * s.bending_slope[2 * node] / l;
    at(NodalDof::kRz) =
        force.y() * l * s.bending[2 * node + 1] + moment.z() * s.bending_slope[2 * node + 1];
    at(NodalDof::kRx) = moment.x() * s.bar[node];
    // x-z plane: w = uz, theta = dw/dx = -r_y, and a moment about y does work -C_y dw/dx.
    at(NodalDof::kUz) =
        force.z() * s.bending[2 * node] - moment.y() * s.bending_slope[2 * node] / l;
    at(NodalDof::kRy) =
        -force.z() * l * s.bending[2 * node + 1] + moment.y() * s.bending_slope[2 * node + 1];
  }
  return f;
}

/// The consistent nodal loads of a uniform load q per unit length over an element of length l.
/// Three-point Gauss-Legendre integrates the cubic shape functions exactly.
inline ElementLoads UniformElementLoads(const FrameBases& bases, double l,
                                        const Eigen::Vector3d& q) {
  const double nodes[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
  const double weights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
  ElementLoads f = ElementLoads::Zero();
  for (int g = 0; g < 3; ++g) {
    f += PointElementLoads(bases, l, nodes[g], q * (l * weights[g]), Eigen::Vector3d::Zero());
  }
  return f;
}

}  // namespace cosmems
