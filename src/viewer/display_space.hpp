#pragma once

#include <Eigen/Core>

namespace cosmems::viewer {

/// The 3-D view's world: micrometres, the beam's axes (x along the beam from the first support,
/// y away from the substrate, z across the width), with y stretched by `exaggeration` so that
/// deflections of a few micrometres show on a beam hundreds long. The panel says the factor.
struct DisplaySpace {
  double exaggeration = 5.0;

  Eigen::Vector3d ToWorld(const Eigen::Vector3d& micro_m) const {
    return Eigen::Vector3d(1e6 * micro_m.x(), 1e6 * exaggeration * micro_m.y(), 1e6 * micro_m.z());
  }
  Eigen::Vector3d ToMicro(const Eigen::Vector3d& world) const {
    return Eigen::Vector3d(1e-6 * world.x(), 1e-6 * world.y() / exaggeration, 1e-6 * world.z());
  }
};

}  // namespace cosmems::viewer
