#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/element_interpolation.hpp"
#include "cosmems/beam/load_case.hpp"
#include "cosmems/core/validation.hpp"

namespace cosmems {

/// The consistent nodal load vector (reduced, internal units) of a LoadCase: each load is
/// weighted by the static shape functions, so a point force between nodes and a uniform load
/// produce exactly the work-equivalent nodal forces and moments.
///
/// Throws std::invalid_argument for a load outside the beam, a non-finite value, or an
/// out-of-plane component on a planar (Dim = 2) model.
template <int Dim>
Eigen::VectorXd AssembleLoads(const BeamModel<Dim>& model, const LoadCase& loads) {
  const UnitSystem& units = model.units();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.FreeDofCount());
  auto add = [&](int element, int node, NodalDof dof, double value) {
    const int r = model.dofs().Reduced(element + node, dof);
    if (r >= 0) f[r] += value;
  };
  auto check_plane = [](const char* what, double value) {
    if (Dim == 2 && value != 0.0) {
      throw std::invalid_argument(std::string(what) + " = " + FormatValue(value) +
                                  ": out of plane for a planar (dimension = 2) model");
    }
  };
  // Generalised forces of a force F and moment C acting at local coordinate xi of element e.
  auto apply = [&](int e, double xi, const Eigen::Vector3d& force, const Eigen::Vector3d& moment) {
    const double l = model.elements()[e].properties().length;
    const ShapeValues s = ShapeValues::At(model.bases(), xi);
    for (int node = 0; node < 2; ++node) {
      add(e, node, NodalDof::kUx, force.x() * s.bar[node]);
      add(e, node, NodalDof::kUy,
          force.y() * s.bending[2 * node] + moment.z() * s.bending_slope[2 * node] / l);
      add(e, node, NodalDof::kRz,
          force.y() * l * s.bending[2 * node + 1] + moment.z() * s.bending_slope[2 * node + 1]);
      if constexpr (Dim == 3) {
        add(e, node, NodalDof::kRx, moment.x() * s.bar[node]);
        // x-z plane: w = uz, theta = dw/dx = -r_y, and a moment about y does work -C_y dw/dx.
        add(e, node, NodalDof::kUz,
            force.z() * s.bending[2 * node] - moment.y() * s.bending_slope[2 * node] / l);
        add(e, node, NodalDof::kRy,
            -force.z() * l * s.bending[2 * node + 1] + moment.y() * s.bending_slope[2 * node + 1]);
      }
    }
  };

  for (const PointLoad& load : loads.points) {
    for (int k = 0; k < 3; ++k) {
      RequireFinite("load force", load.force[k]);
      RequireFinite("load moment", load.moment[k]);
    }
    const double length = model.description().Length();
    if (!(load.x >= 0.0 && load.x <= length * (1.0 + 1e-12))) {
      throw std::invalid_argument("load position x = " + FormatValue(load.x) +
                                  " m: outside the beam (0 ... " + FormatValue(length) + " m)");
    }
    check_plane("load force z", load.force.z());
    check_plane("load moment x", load.moment.x());
    check_plane("load moment y", load.moment.y());
    const auto [e, xi] = model.Locate(load.x / units.length);
    apply(e, xi, load.force / units.force, load.moment / units.Moment());
  }

  const Eigen::Vector3d q = loads.distributed / units.ForcePerLength();
  for (int k = 0; k < 3; ++k) RequireFinite("distributed load", loads.distributed[k]);
  check_plane("distributed load z", loads.distributed.z());
  if (!q.isZero(0.0)) {
    // A uniform load integrates the shape functions exactly with 3-point Gauss-Legendre
    // (cubics are integrated exactly by any rule of degree >= 3).
    const double nodes[3] = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    const double weights[3] = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};
    for (int e = 0; e < model.ElementCount(); ++e) {
      const double l = model.elements()[e].properties().length;
      for (int g = 0; g < 3; ++g) apply(e, nodes[g], q * (l * weights[g]), Eigen::Vector3d::Zero());
    }
  }
  return f;
}

}  // namespace cosmems
