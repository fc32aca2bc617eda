#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <stdexcept>
#include <string>

#include "cosmems/beam/load_case.hpp"
#include "cosmems/core/validation.hpp"
#include "cosmems/rod/cosserat_rod.hpp"
#include "cosmems/rod/rod_loads.hpp"

namespace cosmems {

/// The rod's loads for a beam's LoadCase (SI): the nodal forces that do the same work as the
/// given loads on the rod's elements, which interpolate displacements linearly. A point force at
/// a fraction s of an element goes (1 - s) and s to its two nodes; the distributed load gives
/// each node q times half the length of its elements. All of them are dead loads: they keep
/// their direction however far the rod turns. A point moment is the rod's end moment (a true
/// couple) and must act at the last node: the rod takes no moments elsewhere, and
/// std::invalid_argument says so naming the load.
inline RodLoads RodLoadsFor(const CosseratRod& rod, const LoadCase& loads) {
  const BeamDescription& beam = rod.description();
  const double length = beam.Length();
  for (int k = 0; k < 3; ++k) RequireFinite("distributed load", loads.distributed[k]);
  RodLoads out = RodLoads::None(rod.NodeCount());
  for (std::size_t e = 0; e < beam.elements.size(); ++e) {
    const double h = beam.elements[e].length;
    out.dead_forces.col(e) += 0.5 * h * loads.distributed;
    out.dead_forces.col(e + 1) += 0.5 * h * loads.distributed;
  }
  for (const PointLoad& load : loads.points) {
    for (int k = 0; k < 3; ++k) {
      RequireFinite("load force", load.force[k]);
      RequireFinite("load moment", load.moment[k]);
    }
    if (!(load.x >= 0.0 && load.x <= length * (1.0 + 1e-12))) {
      throw std::invalid_argument("load position x = " + FormatValue(load.x) +
                                  " m: outside the beam (0 ... " + FormatValue(length) + " m)");
    }
    double start = 0.0;
    std::size_t e = 0;
    while (e + 1 < beam.elements.size() && load.x > start + beam.elements[e].length) {
      start += beam.elements[e].length;
      ++e;
    }
    const double s = std::clamp((load.x - start) / beam.elements[e].length, 0.0, 1.0);
    out.dead_forces.col(e) += (1.0 - s) * load.force;
    out.dead_forces.col(e + 1) += s * load.force;
    if (load.moment.isZero(0.0)) continue;
    if (load.x < length * (1.0 - 1e-12)) {
      throw std::invalid_argument("load moment at x = " + FormatValue(load.x) +
                                  " m: a Cosserat rod takes a moment at its last node only (x = " +
                                  FormatValue(length) + " m)");
    }
    out.end_moment += load.moment;
  }
  return out;
}

}  // namespace cosmems
