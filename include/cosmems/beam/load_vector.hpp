#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>

#include "cosmems/beam/beam_model.hpp"
#include "cosmems/beam/element_loads.hpp"
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
  auto scatter = [&](int e, const ElementLoads& local) {
    for (int a = 0; a < 12; ++a) add(e, a / 6, static_cast<NodalDof>(a % 6), local[a]);
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
    scatter(e, PointElementLoads(model.bases(), model.elements()[e].properties().length, xi,
                                 load.force / units.force, load.moment / units.Moment()));
  }

  const Eigen::Vector3d q = loads.distributed / units.ForcePerLength();
  for (int k = 0; k < 3; ++k) RequireFinite("distributed load", loads.distributed[k]);
  check_plane("distributed load z", loads.distributed.z());
  if (!q.isZero(0.0)) {
    for (int e = 0; e < model.ElementCount(); ++e) {
      scatter(e, UniformElementLoads(model.bases(), model.elements()[e].properties().length, q));
    }
  }
  return f;
}

}  // namespace cosmems
