#pragma once

#include <Eigen/Core>

namespace cosmems {

/// Loads on a rod, in SI at the public interface (a model converts them once to its internal
/// units).
///
/// - Dead forces keep their direction in space.
/// - The follower force acts at the last node (the free end of a cantilever) and turns with its
///   directors: F = R_N F0, F0 being the force it exerts on the undeformed rod (its components
///   on d1, d2, d3). It is not conservative: its load stiffness is not symmetric.
/// - The end moment acts at the last node with an axis fixed in space: a true couple, not a
///   pair of forces. In the Newton matrix it brings the skew block -[M]x / 2 (the exponential
///   chart's term), so Newton stays quadratic also in 3-D.
struct RodLoads {
  Eigen::Matrix3Xd dead_forces;                              ///< N, one column per node
  Eigen::Vector3d follower_force = Eigen::Vector3d::Zero();  ///< N, F0 at the last node
  Eigen::Vector3d end_moment = Eigen::Vector3d::Zero();      ///< N m, at the last node

  /// No load on a rod of `nodes` nodes.
  static RodLoads None(int nodes) {
    RodLoads loads;
    loads.dead_forces.setZero(3, nodes);
    return loads;
  }

  /// Loads at the last node only: a dead force [N], a follower force [N] and a moment [N m].
  static RodLoads AtEnd(int nodes, const Eigen::Vector3d& dead_force,
                        const Eigen::Vector3d& follower_force, const Eigen::Vector3d& moment) {
    RodLoads loads = None(nodes);
    loads.dead_forces.col(nodes - 1) = dead_force;
    loads.follower_force = follower_force;
    loads.end_moment = moment;
    return loads;
  }

  /// (1 - s) a + s b into `out` (already of the same shape): a load path. Allocates nothing.
  static void Interpolate(const RodLoads& a, const RodLoads& b, double s, RodLoads& out) {
    out.dead_forces = (1.0 - s) * a.dead_forces + s * b.dead_forces;
    out.follower_force = (1.0 - s) * a.follower_force + s * b.follower_force;
    out.end_moment = (1.0 - s) * a.end_moment + s * b.end_moment;
  }
};

}  // namespace cosmems
